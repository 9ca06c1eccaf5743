#!/usr/bin/env bash
# Runs the recipes of doc pages (doc/python.md, doc/octave.md) exactly as
# printed, the way a new user does after cloning: on a fresh copy of the
# source tree (tracked files, plus untracked ones not ignored), with HOME at
# a scratch directory (the recipes' $HOME/opt/creepwork prefix is private)
# and `python3` the interpreter CMake chose (one with numpy). Blocks come
# from scripts/readme-block.sh (the README's markers): each "file" block
# must equal that file of the tree (the page shows the real example), each
# "recipe" block runs in page order in its own bash -euo pipefail from the
# top of the copy, and a recipe with an "output" block must print exactly
# that.
# usage: run_doc_recipes.sh <source dir> <work dir> <python3> <page.md>...
set -euo pipefail
src=$(cd "${1:?source dir}" && pwd)
work=${2:?work dir}
python=${3:?python3}
shift 3
blocks="$src/scripts/readme-block.sh"

rm -rf "$work"
mkdir -p "$work/clone" "$work/home" "$work/bin"
work=$(cd "$work" && pwd)
(cd "$src" && git ls-files -z --cached --others --exclude-standard | tar --null -T - -cf -) |
  tar -xf - -C "$work/clone"
ln -s "$python" "$work/bin/python3"
export PATH="$work/bin:$PATH"
export HOME="$work/home"
cd "$work/clone"

ran=0
for page in "$@"; do
  mapfile -t entries < <(bash "$blocks" "$page" list)
  for entry in "${entries[@]}"; do
    read -r kind name <<<"$entry"
    case "$kind" in
      file)
        if ! diff <(bash "$blocks" "$page" file "$name") "$name"; then
          echo "FAILED: $page shows another $name than the tree has (diff above)" >&2
          exit 1
        fi
        ;;
      recipe)
        echo "=== $(basename "$page") recipe $name"
        if ! bash -euo pipefail <(bash "$blocks" "$page" recipe "$name") >"$work/$name.out" \
            2>"$work/$name.err"; then
          tail -n 40 "$work/$name.out" "$work/$name.err"
          echo "FAILED: recipe '$name' of $page (output in $work/$name.out, .err)" >&2
          exit 1
        fi
        if grep -qx "output $name" <(printf '%s\n' "${entries[@]}"); then
          if ! diff <(bash "$blocks" "$page" output "$name") "$work/$name.out"; then
            echo "FAILED: recipe '$name' printed other output than $page shows (< page, > actual)" >&2
            exit 1
          fi
          echo "    output as the page shows"
        fi
        ran=$((ran + 1))
        ;;
    esac
  done
done
[ "$ran" -gt 0 ] || { echo "no recipes found in $*" >&2; exit 1; }
echo "all $ran recipes ran as printed"
