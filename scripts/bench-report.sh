#!/usr/bin/env bash
# Every timing table of doc/performance.md, measured now, each under a
# one-line stamp: CPU, compiler and flags, the commit measured, the date and
# the load average. ./run bench runs it with --update doc/performance.md.
# Timing is not deterministic, so no test checks the numbers; doc_check
# checks that every table of the page sits under such a stamp.
#
# A timing table sits between two marker lines of doc/performance.md:
#   <!-- timing: SECTION -->
#   (blank line, the stamp, blank line, the tables, blank line)
#   <!-- end timing -->
# and SECTION is one of (with what it runs, from the build's bin/):
#   fastsim        creepwork_bench --exact-grids 0   FASTSIM, every layer, batch
#   exact          creepwork_bench --exact-only      the exact model, cold and warm
#   jacobian       creepwork_bench_jacobian
#   wear           creepwork_bench_wear
#   temperature    creepwork_bench_temperature
#   calibrated     creepwork_calibration time
#   nonhertz       creepwork_bench_nonhertz          CONTACT beside it (needs CONTACT)
#   wheelrail      creepwork_bench_wheelrail 200     CONTACT beside it (needs CONTACT)
#   transient      creepwork_bench_transient 20      CONTACT beside it (needs CONTACT)
#   friction       creepwork_bench_friction          FASTSIM with a law of the slip speed
#   friction-exact creepwork_bench_friction_exact 5  CONTACT beside it (needs CONTACT)
#   legacy         creepwork_bench_legacy
#   python         python/bench/bench_python.py      the package against the C batch
#   campaign       bench/campaign/bench_campaign.sh  ranks x threads (needs MPI)
#   campaign-wear  the same with --wear
# "needs CONTACT": CONTACT's columns come from the same run, so the section
# is measured only when the build names a CONTACT build
# (-DCREEPWORK_CONTACT_DIR=<dir with bin/libcontact.so, bin/contact and
# CONTACT/examples>; tools/contact_reference says how to build one); otherwise it is left as it
# is, with a note.
#
# The stamp must name a real commit and a quiet machine, so the script
#   - refuses a work tree with changes other than doc/performance.md itself
#     (--allow-dirty measures anyway; the stamp then says so and doc_check
#     refuses it on the page);
#   - before each section, waits up to --wait seconds (default 300) for the
#     1-minute load average to fall below 1.5 (a build's own load decays in
#     about a minute), then refuses (--allow-load measures anyway; the stamp
#     says so and doc_check refuses it on the page).
# Each section's output keeps its tables, the caption line above each, and
# its bitwise checks; the benchmark's own preamble is left out (the page
# describes the set-up).
#
# usage: bench-report.sh BUILD_DIR [--update FILE] [--only S1,S2,...] [--quick]
#                        [--allow-dirty] [--allow-load] [--wait SECONDS] [--list]
#   without --update: print every section (or --only's) as Markdown
#   --quick: fewer, shorter samples where a benchmark has such an option
#            (numbers not for the page: the stamp says --quick)
set -euo pipefail
source_dir=$(cd "$(dirname "$0")/.." && pwd)
all_sections=(fastsim exact jacobian wear temperature calibrated nonhertz wheelrail transient friction friction-exact legacy python campaign campaign-wear)
usage() { sed -n '/^# usage:/,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//' >&2; exit 2; }
build="" update="" only="" quick=0 allow_dirty=0 allow_load=0 wait_max=300 list=0
while [ $# -gt 0 ]; do
  case "$1" in
    --update) update=${2:?--update FILE}; shift 2 ;;
    --only) only=${2:?--only S1,S2}; shift 2 ;;
    --quick) quick=1; shift ;;
    --allow-dirty) allow_dirty=1; shift ;;
    --allow-load) allow_load=1; shift ;;
    --wait) wait_max=${2:?--wait SECONDS}; shift 2 ;;
    --list) list=1; shift ;;
    -h | --help) usage ;;
    -*) echo "bench-report.sh: unknown option $1" >&2; usage ;;
    *) [ -z "$build" ] || usage; build=$1; shift ;;
  esac
done
if [ $list -eq 1 ]; then printf '%s\n' "${all_sections[@]}"; exit 0; fi
[ -n "$build" ] || usage
build=$(cd "$build" && pwd)
cache="$build/CMakeCache.txt"
[ -f "$cache" ] || { echo "bench-report.sh: $build is not a configured build" >&2; exit 2; }
cache_value() { sed -n "s/^$1:[A-Z]*=//p" "$cache" | head -n 1; }

# ------------------------------------------------------------ the stamp
build_type=$(cache_value CMAKE_BUILD_TYPE)
compiler=$("$(cache_value CMAKE_CXX_COMPILER)" --version | head -n 1)
upper=$(tr '[:lower:]' '[:upper:]' <<<"$build_type")
flags=$(echo $(cache_value CMAKE_CXX_FLAGS) $(cache_value "CMAKE_CXX_FLAGS_$upper"))
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo | head -n 1)
cores=$(nproc 2>/dev/null || echo "?")
commit=$(git -C "$source_dir" rev-parse --short=7 HEAD 2>/dev/null || true)
[ -n "$commit" ] || { echo "bench-report.sh: not a git checkout: no commit to stamp" >&2; exit 1; }
page_rel=""
[ -n "$update" ] && page_rel=$(realpath -m --relative-to="$source_dir" "$update")
changes=$(git -C "$source_dir" status --porcelain --untracked-files=normal | grep -v " $page_rel\$" || true)
[ -n "$page_rel" ] || changes=$(git -C "$source_dir" status --porcelain --untracked-files=normal)
tree_note=""
if [ -n "$changes" ]; then
  if [ $allow_dirty -eq 0 ]; then
    echo "bench-report.sh: the work tree has changes; a stamp must name the commit measured:" >&2
    echo "$changes" | head -n 10 >&2
    echo "commit them (or stash them), or pass --allow-dirty for numbers not for the page" >&2
    exit 1
  fi
  tree_note=" with uncommitted changes (not for the page)"
fi
if [ -n "$update" ] && { [ -n "$tree_note" ] || [ $quick -eq 1 ]; }; then
  echo "bench-report.sh: --update takes only a clean tree and full samples (no --allow-dirty changes, no --quick)" >&2
  exit 2
fi

load1() { cut -d' ' -f1 /proc/loadavg; }
below() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }
# quiet: waits for the load average to fall below 1.5; sets load_note.
quiet() {
  local waited=0
  while ! below "$(load1)" 1.5 && [ $waited -lt "$wait_max" ]; do
    [ $waited -eq 0 ] && echo "  waiting for the load average ($(load1)) to fall below 1.5 ..." >&2
    sleep 10
    waited=$((waited + 10))
  done
  start_load=$(load1)
  if below "$start_load" 1.5; then
    load_note="load average $start_load at the start (below 1.5)"
  elif [ $allow_load -eq 1 ]; then
    load_note="load average $start_load at the start, above 1.5 (not for the page)"
  else
    echo "bench-report.sh: load average $start_load after ${waited} s: other work would be timed too." >&2
    echo "Measure on a quiet machine, or pass --allow-load for numbers not for the page." >&2
    exit 1
  fi
}
stamp() { # stamp EXTRA
  printf '*Measured by `./run bench` on %s (%s cores), %s, %s, flags "%s", commit %s%s, %s, %s, %s at the end%s%s.*\n' \
    "$cpu" "$cores" "$compiler" "$build_type" "$flags" "$commit" "$tree_note" "$(date -u +%Y-%m-%d)" \
    "$load_note" "$(load1)" "$1" "$([ $quick -eq 1 ] && echo '; --quick: short samples, not for the page')"
}

# ---------------------------------------------------------- the sections
bin="$build/bin"
contact_dir=$(cache_value CREEPWORK_CONTACT_DIR)
python=$(cache_value Python3_EXECUTABLE)
q() { [ $quick -eq 1 ] && echo "$1"; true; }
# needs SECTION: "" when the section can run, else why not.
needs() {
  local programs=()
  case "$1" in
    fastsim | exact) programs=(creepwork_bench) ;;
    jacobian) programs=(creepwork_bench_jacobian) ;;
    wear) programs=(creepwork_bench_wear) ;;
    temperature) programs=(creepwork_bench_temperature) ;;
    calibrated) programs=(creepwork_calibration) ;;
    nonhertz) programs=(creepwork_bench_nonhertz) ;;
    wheelrail) programs=(creepwork_bench_wheelrail) ;;
    transient) programs=(creepwork_bench_transient) ;;
    friction) programs=(creepwork_bench_friction) ;;
    friction-exact) programs=(creepwork_bench_friction_exact) ;;
    legacy) programs=(creepwork_bench_legacy) ;;
    python) programs=(creepwork_bench_python_batch) ;;
    campaign | campaign-wear) programs=(creepwork creepwork-campaign) ;;
    *) echo "no such section (bench-report.sh --list)"; return ;;
  esac
  for p in "${programs[@]}"; do
    [ -x "$bin/$p" ] || { echo "$bin/$p is not built"; return; }
  done
  case "$1" in
    nonhertz | wheelrail | transient | friction-exact)
      if [ -z "$contact_dir" ] || [ ! -x "$contact_dir/bin/contact" ] || [ ! -d "$contact_dir/CONTACT/examples" ]; then
        echo "CONTACT's columns need a CONTACT build: configure with -DCREEPWORK_CONTACT_DIR=<dir>"
        return
      fi ;;
    python)
      [ -n "$python" ] && "$python" -c "import numpy" 2>/dev/null || { echo "no python3 with numpy"; return; }
      [ -f "$build/python/creepwork/_layout.py" ] || { echo "the Python package is not staged in $build/python"; return; } ;;
    campaign | campaign-wear)
      command -v "${MPIRUN:-mpirun}" >/dev/null || { echo "no mpirun"; return; } ;;
  esac
}
stamp_extra() {
  case "$1" in
    python) printf '; Python %s, numpy %s' "$("$python" -c 'import platform; print(platform.python_version())')" \
              "$("$python" -c 'import numpy; print(numpy.__version__)')" ;;
    nonhertz | wheelrail | transient | friction-exact) printf '; CONTACT built in %s' "$contact_dir" ;;
    campaign | campaign-wear) printf '; %s' "$("${MPIRUN:-mpirun}" --version 2>/dev/null | head -n 1)" ;;
  esac
}
run_section() {
  case "$1" in
    fastsim) "$bin/creepwork_bench" --exact-grids 0 $(q --quick) ;;
    exact) "$bin/creepwork_bench" --exact-only $(q "--exact-grids 20,40 --exact-steps 100") ;;
    jacobian) "$bin/creepwork_bench_jacobian" ;;
    wear) "$bin/creepwork_bench_wear" ;;
    temperature) "$bin/creepwork_bench_temperature" ;;
    calibrated) "$bin/creepwork_calibration" time ;;
    nonhertz)
      # In $work: CONTACT's library writes contact_addon.out into the working directory.
      (cd "$work" && GLIBC_TUNABLES=glibc.malloc.trim_threshold=536870912:glibc.malloc.mmap_threshold=33554432:glibc.malloc.top_pad=67108864 \
        "$bin/creepwork_bench_nonhertz" $(q --quick)) ;;
    wheelrail)
      (cd "$work" && "$bin/creepwork_bench_wheelrail" "$([ $quick -eq 1 ] && echo 10 || echo 200)" \
        "$contact_dir/bin/contact" "$contact_dir/CONTACT/examples") ;;
    transient)
      (cd "$work" && "$bin/creepwork_bench_transient" "$([ $quick -eq 1 ] && echo 3 || echo 20)" \
        "$contact_dir/bin/contact" "$contact_dir/CONTACT/examples") ;;
    friction) "$bin/creepwork_bench_friction" ;;
    friction-exact)
      (cd "$work" && "$bin/creepwork_bench_friction_exact" "$([ $quick -eq 1 ] && echo 1 || echo 5)" \
        "$contact_dir/bin/contact") ;;
    legacy) "$bin/creepwork_bench_legacy" ;;
    python)
      PYTHONPATH="$build/python" PYTHONDONTWRITEBYTECODE=1 "$python" "$source_dir/python/bench/bench_python.py" \
        --c-program "$bin/creepwork_bench_python_batch" $(q "--count 2000 --rounds 1") ;;
    campaign) bash "$source_dir/bench/campaign/bench_campaign.sh" "$bin/creepwork" $(q "2000 24 1") ;;
    campaign-wear)
      # shellcheck disable=SC2046 # the counts are three words
      WEAR=1 bash "$source_dir/bench/campaign/bench_campaign.sh" "$bin/creepwork" \
        $([ $quick -eq 1 ] && echo "2000 24 1" || echo "50000 96 2") ;;
  esac
}
# page_text: the benchmark's tables, the one-line caption above each, and
# its bitwise checks; nothing else (awk over blank-line separated paragraphs).
page_text() {
  awk 'function flush() {
         if (n == 0) return
         para[++np] = text; lines[np] = n; table[np] = (tab == n); n = 0; text = ""; tab = 0
       }
       /^[[:space:]]*$/ { flush(); next }
       { text = (n ? text "\n" : "") $0; n++; if ($0 ~ /^\|/) tab++ }
       END {
         flush(); out = 0
         for (k = 1; k <= np; k++) {
           keep = table[k] || para[k] ~ /bitwise/ || (lines[k] == 1 && k < np && table[k + 1])
           if (keep) { printf "%s%s\n", (out ? "\n" : ""), para[k]; out = 1 }
         }
       }'
}

sections=("${all_sections[@]}")
if [ -n "$update" ]; then
  [ -f "$update" ] || { echo "bench-report.sh: no file $update" >&2; exit 2; }
  mapfile -t sections < <(sed -n 's/^<!-- timing: \([a-z-]*\) -->$/\1/p' "$update")
fi
if [ -n "$only" ]; then
  IFS=, read -r -a wanted <<<"$only"
  for w in "${wanted[@]}"; do
    [ -z "$(needs "$w" | grep 'no such section')" ] || { echo "bench-report.sh: no section $w" >&2; exit 2; }
  done
  kept=()
  for s in "${sections[@]}"; do
    for w in "${wanted[@]}"; do [ "$s" = "$w" ] && kept+=("$s"); done
  done
  sections=("${kept[@]}")
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
total_start=$SECONDS
measured=()
for s in "${sections[@]}"; do
  why=$(needs "$s")
  if [ -n "$why" ]; then
    echo "bench-report.sh: $s left as it is: $why" >&2
    continue
  fi
  quiet
  start=$SECONDS
  echo "  measuring $s ..." >&2
  run_section "$s" >"$work/$s.raw" 2>"$work/$s.err" || {
    cat "$work/$s.err" >&2
    echo "bench-report.sh: $s failed" >&2
    exit 1
  }
  { echo; stamp "$(stamp_extra "$s")"; echo; page_text <"$work/$s.raw"; echo; } >"$work/$s.md"
  echo "  $s: $((SECONDS - start)) s" >&2
  measured+=("$s")
  if [ -z "$update" ]; then
    printf '\n## %s\n' "$s"
    cat "$work/$s.md"
  fi
done

if [ -n "$update" ]; then
  # Each measured section's block replaced by its new text; the others kept.
  awk -v dir="$work" '
    /^<!-- timing: [a-z-]+ -->$/ {
      print; name = $3; file = dir "/" name ".md"
      if ((getline line < file) > 0) {
        print line; while ((getline line < file) > 0) print line; close(file); skip = 1
      }
      next
    }
    /^<!-- end timing -->$/ { skip = 0 }
    !skip { print }' "$update" >"$work/page.md"
  cp "$work/page.md" "$update"
  echo "bench-report.sh: ${#measured[@]} of ${#sections[@]} sections of $page_rel measured (${measured[*]:-none}) in $((SECONDS - total_start)) s" >&2
fi
