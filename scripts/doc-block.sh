#!/usr/bin/env bash
# Prints the blocks of README.md and doc/**/*.md that tests run or compare,
# so the documentation cannot drift from what they run. A block is the
# fenced code block right after a marker comment:
#   <!-- recipe: NAME -->     shell commands run by tests/install, in order
#   <!-- recipe-ci: NAME -->  shell commands run by scripts/test-all.sh
#   <!-- file: PATH -->       a file the recipes need, written to PATH
#   <!-- output: NAME -->     what recipe NAME must print, exactly
#   <!-- copy: NAME -->       the recipe NAME shown again for reading; equal to
#                             it (scripts/doc-check.sh), never run twice
# Names are unique over all the files (run_doc_recipes.sh checks it).
# usage: doc-block.sh files [SOURCE_DIR]       # the documents, in run order
#        doc-block.sh <FILE.md> list           # KIND NAME per line, in order
#        doc-block.sh <FILE.md> <KIND> <NAME>  # that block's body
set -euo pipefail
if [ "${1:-}" = files ]; then
  # README.md first (it holds the install recipe the others build on), then
  # the manual's pages in path order; doc/dev/ holds no recipes.
  cd "${2:-.}"
  echo README.md
  find doc -name '*.md' -not -path 'doc/dev/*' | LC_ALL=C sort
  exit 0
fi
doc=${1:?usage: doc-block.sh files | <FILE.md> list | <FILE.md> <kind> <name>}
if [ "${2:-}" = list ]; then
  sed -n 's/^<!-- \(recipe\|recipe-ci\|file\|output\|copy\): \([^ ]*\) -->$/\1 \2/p' "$doc"
  exit 0
fi
kind=${2:?kind}
name=${3:?name}
awk -v marker="<!-- $kind: $name -->" '
  $0 == marker { armed = 1; next }
  armed && /^```/ { if (inside) exit; inside = 1; next }
  inside { print; found = 1 }
  END { if (!found) { print "no block " marker > "/dev/stderr"; exit 1 } }
' "$doc"
