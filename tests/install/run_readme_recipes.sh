#!/usr/bin/env bash
# Runs every install-and-use recipe of README.md exactly as printed, the way
# a new user does after cloning: on a fresh copy of the source tree (the
# tracked files, plus untracked ones not ignored), with HOME pointing at a
# scratch directory so that the recipes' $HOME/opt/creepwork prefix is
# private. Blocks come from scripts/readme-block.sh: "file" blocks are
# written first, "recipe" blocks run in README order (each in its own bash
# -euo pipefail, from the top of the copy), and a recipe with an "output"
# block must print exactly that. recipe-ci blocks are CI's first stage and
# run there (scripts/test-all.sh), not here.
# usage: run_readme_recipes.sh <source dir> <work dir>
set -euo pipefail
src=$(cd "${1:?source dir}" && pwd)
work=${2:?work dir}
blocks="$src/scripts/readme-block.sh"
readme="$src/README.md"

rm -rf "$work"
mkdir -p "$work/clone" "$work/home"
work=$(cd "$work" && pwd)
if git -C "$src" rev-parse --show-toplevel >/dev/null 2>&1; then
  (cd "$src" && git ls-files -z --cached --others --exclude-standard |
     tar --null -T - -cf -) | tar -xf - -C "$work/clone"
else
  (cd "$src" && tar --exclude='./build*' --exclude=./out -cf - .) | tar -xf - -C "$work/clone"
fi
cd "$work/clone"
export HOME="$work/home"

mapfile -t entries < <(bash "$blocks" "$readme" list)
ran=0
for entry in "${entries[@]}"; do
  read -r kind name <<<"$entry"
  [ "$kind" = file ] || continue
  mkdir -p "$(dirname "$name")"
  bash "$blocks" "$readme" file "$name" >"$name"
done
for entry in "${entries[@]}"; do
  read -r kind name <<<"$entry"
  [ "$kind" = recipe ] || continue
  echo "=== recipe $name"
  bash "$blocks" "$readme" recipe "$name" | sed 's/^/    /'
  if ! bash -euo pipefail <(bash "$blocks" "$readme" recipe "$name") >"$work/$name.out" \
      2>"$work/$name.err"; then
    tail -n 40 "$work/$name.out" "$work/$name.err"
    echo "FAILED: README recipe '$name' (output in $work/$name.out, .err)" >&2
    exit 1
  fi
  if grep -qx "output $name" <(printf '%s\n' "${entries[@]}"); then
    if ! diff <(bash "$blocks" "$readme" output "$name") "$work/$name.out"; then
      echo "FAILED: README recipe '$name' printed other output than README shows (diff above: < README, > actual)" >&2
      exit 1
    fi
    echo "    output as README shows"
  fi
  ran=$((ran + 1))
done
[ "$ran" -gt 0 ] || { echo "no recipes found in $readme" >&2; exit 1; }
echo "all $ran README recipes ran as printed"
