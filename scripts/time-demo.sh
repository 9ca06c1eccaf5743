#!/usr/bin/env bash
# Times `./run demo` as a new user meets it: in a fresh clone of a commit
# (HEAD by default), without ccache (a user has no warm cache), printing
# the load average before and after, the wall and CPU time of the whole
# run, and the demo's own phase times (configure, build, figures).
#   scripts/time-demo.sh [<commit>] [<work dir>]
# The number README.md quotes is a run of this on an idle 2-core machine
# (load average below 1).
set -euo pipefail
top=$(cd "$(dirname "$0")/.." && pwd)
commit=${1:-HEAD}
work=${2:-${TMPDIR:-/tmp}/creepwork-time-demo}
load() { cut -d' ' -f1-3 /proc/loadavg; }

rm -rf "$work"
git clone -q --no-checkout "$top" "$work"
git -C "$work" checkout -q --detach "$(git -C "$top" rev-parse "$commit")"
cd "$work"
echo "./run demo at $(git rev-parse --short HEAD), fresh clone in $work; load average $(load)"
export CCACHE_DISABLE=1
unset CMAKE_C_COMPILER_LAUNCHER CMAKE_CXX_COMPILER_LAUNCHER
/usr/bin/time -f "%e %U %S" -o "$work/time.txt" ./run demo >"$work/demo.log" 2>&1 ||
  { tail -n 30 "$work/demo.log"; echo "./run demo failed: $work/demo.log" >&2; exit 1; }
read -r wall user sys <"$work/time.txt"
grep '^demo:' "$work/demo.log" || true
echo "./run demo: $wall s wall, $(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.1f", u + s }') s CPU" \
  "(user $user s, sys $sys s); load average after $(load)"
