#!/usr/bin/env bash
# Runs every install-and-use recipe of README.md and of the manual (doc/)
# exactly as printed, the way a new user does after cloning: on a fresh copy
# of the source tree (the tracked files, plus untracked ones not ignored),
# with HOME pointing at a scratch directory so that the recipes'
# $HOME/opt/creepwork prefix is private. Blocks come from
# scripts/doc-block.sh: "file" blocks of every document are written first,
# then "recipe" blocks run in document order (README.md first: it holds the
# install recipe; each recipe in its own bash -euo pipefail, from the top of
# the copy), and a recipe with an "output" block must print exactly that.
# recipe-ci blocks are CI's first stage and run there (scripts/test-all.sh).
# usage: run_doc_recipes.sh <source dir> <work dir> [NAME...]
#   NAMEs: run only these recipes (after the install recipe), for quick checks
set -euo pipefail
src=$(cd "${1:?source dir}" && pwd)
work=${2:?work dir}
shift 2
only=("$@")
blocks="$src/scripts/doc-block.sh"

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
# ccache keeps its cache under HOME: the one of the build that runs this,
# so that the recipes' builds of the same sources are look-ups.
if command -v ccache >/dev/null; then
  CCACHE_DIR=${CCACHE_DIR:-$(ccache -k cache_dir)}
  export CCACHE_DIR
fi
export HOME="$work/home"

# PATH stays the user's: a recipe that works only with a particular python3
# first on PATH must say so itself (doc/python.md names /usr/bin/python3).

# Every block as "FILE KIND NAME", in run order; a name used twice is an
# error (recipes and outputs pair by name, files would overwrite).
mapfile -t docs < <(bash "$blocks" files .)
entries=()
for doc in "${docs[@]}"; do
  while read -r kind name; do
    [ -n "$kind" ] && entries+=("$doc $kind $name")
  done < <(bash "$blocks" "$doc" list)
done
dups=$(printf '%s\n' "${entries[@]}" | awk '{ print $2, $3 }' | sort | uniq -d)
if [ -n "$dups" ]; then
  echo "FAILED: block names used more than once across README.md and doc/: $dups" >&2
  exit 1
fi

for entry in "${entries[@]}"; do
  read -r doc kind name <<<"$entry"
  [ "$kind" = file ] || continue
  mkdir -p "$(dirname "$name")"
  bash "$blocks" "$doc" file "$name" >"$name"
done
ran=0
for entry in "${entries[@]}"; do
  read -r doc kind name <<<"$entry"
  [ "$kind" = recipe ] || continue
  if [ ${#only[@]} -gt 0 ] && [ "$name" != install ] &&
     ! printf '%s\n' "${only[@]}" | grep -qx "$name"; then
    continue
  fi
  echo "=== recipe $name ($doc)"
  bash "$blocks" "$doc" recipe "$name" | sed 's/^/    /'
  if ! bash -euo pipefail <(bash "$blocks" "$doc" recipe "$name") >"$work/$name.out" \
      2>"$work/$name.err"; then
    tail -n 40 "$work/$name.out" "$work/$name.err"
    echo "FAILED: recipe '$name' of $doc (output in $work/$name.out, .err)" >&2
    exit 1
  fi
  output_doc=$(printf '%s\n' "${entries[@]}" | awk -v n="$name" '$2 == "output" && $3 == n { print $1 }')
  if [ -n "$output_doc" ]; then
    if ! diff <(bash "$blocks" "$output_doc" output "$name") "$work/$name.out"; then
      echo "FAILED: recipe '$name' printed other output than $output_doc shows (diff above: < document, > actual)" >&2
      exit 1
    fi
    echo "    output as $output_doc shows"
  fi
  ran=$((ran + 1))
done
[ "$ran" -gt 0 ] || { echo "no recipes found in ${docs[*]}" >&2; exit 1; }
echo "all $ran recipes of README.md and doc/ ran as printed"
