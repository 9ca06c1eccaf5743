#!/usr/bin/env bash
# Prints README.md's blocks that are run or compared by tests, so the README
# cannot drift from what they run. A block is the fenced code block right
# after a marker comment:
#   <!-- recipe: NAME -->     shell commands run by tests/install, in order
#   <!-- recipe-ci: NAME -->  shell commands run by scripts/test-all.sh
#   <!-- file: PATH -->       a file the recipes need, written to PATH
#   <!-- output: NAME -->     what recipe NAME must print, exactly
# usage: readme-block.sh <README.md> list            # KIND NAME per line, in order
#        readme-block.sh <README.md> <KIND> <NAME>   # that block's body
set -euo pipefail
readme=${1:?usage: readme-block.sh <README.md> list | <kind> <name>}
if [ "${2:-}" = list ]; then
  sed -n 's/^<!-- \(recipe\|recipe-ci\|file\|output\): \([^ ]*\) -->$/\1 \2/p' "$readme"
  exit 0
fi
kind=${2:?kind}
name=${3:?name}
awk -v marker="<!-- $kind: $name -->" '
  $0 == marker { armed = 1; next }
  armed && /^```/ { if (inside) exit; inside = 1; next }
  inside { print; found = 1 }
  END { if (!found) { print "no block " marker > "/dev/stderr"; exit 1 } }
' "$readme"
