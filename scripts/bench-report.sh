#!/usr/bin/env bash
# Every timing table of doc/performance.md, measured now, each with a
# one-line stamp (CPU, compiler and flags, commit, date, load), printed as
# Markdown for pasting into doc/performance.md. Timing is not deterministic,
# so no test checks these tables; ./run bench runs this script.
# usage: bench-report.sh BUILD_DIR [--quick]
set -euo pipefail
build=$(cd "${1:?usage: bench-report.sh BUILD_DIR [--quick]}" && pwd)
quick=${2:-}
source_dir=$(cd "$(dirname "$0")/.." && pwd)
cache="$build/CMakeCache.txt"
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1; }
build_type=$(cache_value CMAKE_BUILD_TYPE)
compiler=$("$(cache_value CMAKE_CXX_COMPILER)" --version | head -n 1)
upper=$(tr '[:lower:]' '[:upper:]' <<<"$build_type")
flags="$(cache_value CMAKE_CXX_FLAGS) $(cache_value "CMAKE_CXX_FLAGS_$upper")"
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
cores=$(nproc 2>/dev/null || echo "?")
commit=$(git -C "$source_dir" rev-parse --short HEAD 2>/dev/null || echo unknown)
if ! git -C "$source_dir" diff --quiet HEAD 2>/dev/null; then commit="$commit+changes"; fi
stamp() {
  printf '*Measured on %s (%s cores), %s, %s build, flags "%s", commit %s, %s, load average %s.*\n' \
    "$cpu" "$cores" "$compiler" "$build_type" "$(echo $flags)" "$commit" \
    "$(date -u +%Y-%m-%d)" "$(cut -d' ' -f1 /proc/loadavg)"
}
section() { printf '\n## %s\n\n' "$1"; stamp; echo; }

bench_args=()
[ "$quick" = --quick ] && bench_args=(--quick)
section "FASTSIM and the exact model (creepwork_bench)"
"$build/bin/creepwork_bench" "${bench_args[@]}"
section "Jacobians (creepwork_bench_jacobian)"
"$build/bin/creepwork_bench_jacobian"
section "Wear (creepwork_bench_wear)"
"$build/bin/creepwork_bench_wear"
if [ -x "$build/bin/creepwork_calibration" ]; then
  section "Calibrated model (creepwork_calibration time)"
  "$build/bin/creepwork_calibration" time
fi
