#!/usr/bin/env bash
# Every test: the Release build (all CTest tests), then the whole suite under
# AddressSanitizer + UndefinedBehaviorSanitizer, the threaded tests under
# ThreadSanitizer, and a bounded fuzzing run. Any failure fails the run.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

# Stage timings, printed at the end (and on failure); each stage's header
# says which of how many it is (the builds show their percentage, CTest its
# count of tests).
stage_name=""
stage_start=$SECONDS
stage_count=0
stage_total=$(grep -c '^stage "' "$0")
timings=()
end_stage() {
  if [ -n "$stage_name" ]; then
    timings+=("$(printf '%5d s  %s' $((SECONDS - stage_start)) "$stage_name")")
  fi
  stage_name=""
}
stage() {
  end_stage
  stage_name="$*"
  stage_start=$SECONDS
  stage_count=$((stage_count + 1))
  echo
  echo "=== stage $stage_count of $stage_total: $*"
}
report() {
  end_stage
  echo
  echo "stage timings:"
  printf '%s\n' "${timings[@]}"
  printf '%5d s  total\n' "$SECONDS"
}
trap report EXIT

build() { # build <dir> [cmake args...]
  local dir=$1; shift
  mkdir -p "$dir" # the configure log lives inside, where .gitignore covers it
  cmake -S . -B "$dir" "$@" >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log"; exit 1; }
  cmake --build "$dir" -j "$jobs"
}

# Targets to build for the tests carrying a label: each test named after its
# executable target (creepwork_add_test does so); "all" when a test is not.
targets_for_label() { # targets_for_label <dir> <label>
  local known
  known=$(cmake --build "$1" --target help | sed -n 's/^\.\.\. \([^ ]*\).*$/\1/p')
  ctest --test-dir "$1" -N -L "$2" | sed -n 's/^ *Test *#[0-9]*: *\([^ ]*\).*$/\1/p' |
    while read -r name; do
      if grep -qx "$name" <<<"$known"; then echo "$name"; else echo all; fi
    done | sort -u
}

stage "Release build and tests (README's recipe-ci block, as printed)"
# The very commands README.md prints (scripts/doc-block.sh), so the README
# cannot drift from CI. A stale cache goes first: the block relies on the
# options' defaults (every part on), which an earlier configure could have
# changed; object files stay, so nothing is rebuilt needlessly.
rm -f build/CMakeCache.txt
mkdir -p build
bash scripts/doc-block.sh README.md recipe-ci build-and-test >build/readme-build-and-test.sh
bash -euo pipefail build/readme-build-and-test.sh

# The whole suite with ASan + UBSan (gcc: one compiler family for C, C++ and
# Fortran, so gfortran's objects share libasan). Leaks are checked by
# LeakSanitizer at every test's exit. Not built here: the benchmarks (timing
# is meaningless under ASan), the malloc-interposing no-allocation tests and
# the valgrind tests (both need the plain allocator; CMake leaves them out).
# -O1 -g1: the optimisation ASan's documentation asks for and line tables
# for its reports (file and line of every frame); the build takes about half
# the compiler time of -O2 -g, the stage's largest part.
stage "AddressSanitizer + UndefinedBehaviorSanitizer: every test"
asan_flags="-O1 -g1 -DNDEBUG"
build build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo "-DCREEPWORK_SANITIZE=address;undefined" \
  -DCREEPWORK_BUILD_BENCH=OFF "-DCMAKE_C_FLAGS_RELWITHDEBINFO=$asan_flags" \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=$asan_flags" "-DCMAKE_Fortran_FLAGS_RELWITHDEBINFO=$asan_flags"
# verify_asan_link_order=0: programs that load libcreepwork.so without being
# built with ASan (the install-and-consume test) may still run.
# CREEPWORK_ASAN_EXCLUDE (a CTest label regex) can leave out more tests that
# cannot run under ASan; none needs it today. The Python and Octave tests
# (labels python, octave) run here too: CTest preloads libasan and the C++
# runtime into the uninstrumented python3 and octave, with LeakSanitizer off
# in them (python/CMakeLists.txt, creepwork_interpreter_tests).
# The recipes of README.md and doc/ (label "recipes") build their own plain
# library from a fresh copy: under this stage they would only repeat the
# Release stage's run. The documentation's checks (label "docs") compare
# text with what the Release build prints; they test no library code.
asan_exclude=(-LE "recipes|docs${CREEPWORK_ASAN_EXCLUDE:+|$CREEPWORK_ASAN_EXCLUDE}")
ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:detect_stack_use_after_return=1:strict_string_checks=1:verify_asan_link_order=0" \
UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1" \
  ctest --test-dir build-asan --output-on-failure -j "$jobs" "${asan_exclude[@]}"

# The threaded tests (label "threads") with TSan. OpenMP needs care: libgomp
# is not instrumented, so TSan cannot see its barriers and reports every
# result written by a worker and read after the parallel loop (a false
# positive, seen here). So this stage uses clang with LLVM's libomp and its
# Archer tool (libarcher.so, loaded through OMP_TOOL_LIBRARIES), which tells
# TSan about OpenMP's synchronisation; real races inside parallel regions
# are still reported (checked here with a deliberate race). libomp itself is
# not instrumented and orders its internal mutexes with atomics TSan cannot
# see: ignore_noninstrumented_modules=1 (as Archer asks) makes TSan ignore
# the pthread calls such modules make. clang links its TSan runtime
# statically into executables only (the shared runtime crashes on this
# kernel), so the shared library is linked with its TSan symbols left to the
# executable: -z undefs, appended after capi's --no-undefined, which the
# Release stage keeps checking. Only the targets of the threads tests are
# built (with clang for C and C++; Fortran stays gfortran).
stage "ThreadSanitizer: threaded tests (clang, libomp + Archer)"
mkdir -p build-tsan build-fuzz
archer=/usr/lib/llvm-14/lib/libarcher.so
[ -f "$archer" ] || { echo "missing $archer (Debian package libomp-14-dev)"; exit 1; }
CC=clang-14 CXX=clang++-14 cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCREEPWORK_SANITIZE=thread -DCREEPWORK_BUILD_BENCH=OFF -DCREEPWORK_BUILD_EXAMPLES=OFF \
  "-DCMAKE_C_STANDARD_LIBRARIES=-Wl,-z,undefs" "-DCMAKE_CXX_STANDARD_LIBRARIES=-Wl,-z,undefs" \
  >build-tsan/configure.log 2>&1 || { cat build-tsan/configure.log; exit 1; }
mapfile -t tsan_targets < <(targets_for_label build-tsan threads)
[ ${#tsan_targets[@]} -gt 0 ] || { echo "no tests labelled threads"; exit 1; }
if printf '%s\n' "${tsan_targets[@]}" | grep -qx all; then tsan_targets=(all); fi
echo "building: ${tsan_targets[*]}"
cmake --build build-tsan -j "$jobs" --target "${tsan_targets[@]}"
OMP_TOOL_LIBRARIES="$archer" \
TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:ignore_noninstrumented_modules=1" \
  ctest --test-dir build-tsan --output-on-failure -j "$jobs" -L threads

# libFuzzer on the C ABI for a bounded time, starting from the committed
# corpus; new inputs go to a scratch directory, so the corpus is not
# changed. Any crash, sanitizer report, leak or broken invariant fails.
stage "libFuzzer: fuzz_capi for ${CREEPWORK_FUZZ_SECONDS:-60} s"
CC=clang-14 CXX=clang++-14 cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCREEPWORK_BUILD_FUZZ=ON -DCREEPWORK_BUILD_BENCH=OFF -DCREEPWORK_BUILD_EXAMPLES=OFF \
  >build-fuzz/configure.log 2>&1 || { cat build-fuzz/configure.log; exit 1; }
cmake --build build-fuzz -j "$jobs" --target fuzz_capi
rm -rf build-fuzz/new-corpus build-fuzz/artifacts
mkdir -p build-fuzz/new-corpus build-fuzz/artifacts
build-fuzz/bin/fuzz_capi -max_total_time="${CREEPWORK_FUZZ_SECONDS:-60}" -timeout=10 \
  -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix=build-fuzz/artifacts/ \
  build-fuzz/new-corpus tests/fuzz/corpus 2>build-fuzz/fuzz.log ||
  { tail -n 60 build-fuzz/fuzz.log; echo "fuzzing found a problem: build-fuzz/artifacts/"; exit 1; }
grep -E '^stat::(number_of_executed_units|average_exec_per_sec)' build-fuzz/fuzz.log

echo
echo "all test stages passed"
