#!/usr/bin/env bash
# Golden outputs of two commits, compared line by line: the check that a
# refactoring changed no result bit (CONTRIBUTING.md, "House rules").
#   tools/golden/compare.sh <before> [<after>]   (after: the work tree)
# Each side's library is built (core and C ABI only) in
# ${GOLDEN_DIR:-/tmp/creepwork-golden}/<name>; golden_outputs.c of the work
# tree is compiled against each, so both run the same cases.
set -euo pipefail
top=$(git rev-parse --show-toplevel)
work=${GOLDEN_DIR:-/tmp/creepwork-golden}
before=${1:?usage: compare.sh <before> [<after>]}
after=${2:-}
jobs=$(nproc 2>/dev/null || echo 2)

# outputs <name> <source dir>: build the library there and run the cases.
outputs() {
  local name=$1 src=$2 dir=$work/$1
  cmake -S "$src" -B "$dir/build" -DCMAKE_BUILD_TYPE=Release -DCREEPWORK_BUILD_TESTS=OFF \
    -DCREEPWORK_BUILD_EXAMPLES=OFF -DCREEPWORK_BUILD_FORTRAN=OFF -DCREEPWORK_BUILD_CLI=OFF \
    -DCREEPWORK_BUILD_PYTHON=OFF -DCREEPWORK_BUILD_MATLAB=OFF -DCREEPWORK_BUILD_BENCH=OFF \
    >"$dir.configure.log" 2>&1 || { cat "$dir.configure.log"; exit 1; }
  cmake --build "$dir/build" -j "$jobs" --target creepwork >"$dir.build.log" 2>&1 ||
    { tail -n 30 "$dir.build.log"; exit 1; }
  local inc=("-I$src/capi/include" "-I$dir/build/generated/include")
  cc -std=c99 -O1 "${inc[@]}" "$top/tools/golden/golden_outputs.c" -L"$dir/build/lib" \
    -Wl,-rpath,"$dir/build/lib" -lcreepwork -lm -o "$dir/golden_outputs"
  "$dir/golden_outputs" "$top/tests/wheelrail/data" | grep -v '^#' >"$dir.txt"
}

mkdir -p "$work"
rm -rf "$work/before-src"
mkdir -p "$work/before-src"
git -C "$top" archive "$before" | tar -x -C "$work/before-src"
outputs before "$work/before-src"
if [ -n "$after" ]; then
  rm -rf "$work/after-src"
  mkdir -p "$work/after-src"
  git -C "$top" archive "$after" | tar -x -C "$work/after-src"
  outputs after "$work/after-src"
else
  outputs after "$top"
fi
if diff -u "$work/before.txt" "$work/after.txt" >"$work/diff.txt"; then
  echo "golden outputs identical: $(wc -l <"$work/after.txt") cases, $(awk '{n += $3} END {print n}' "$work/after.txt") numbers"
else
  echo "golden outputs differ ($(grep -c '^+[^+]' "$work/diff.txt") cases): $work/diff.txt"
  exit 1
fi
