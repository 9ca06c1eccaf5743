#!/usr/bin/env bash
# A clone builds and passes its tests with nothing beside it: no test, build
# file, script or program of the source tree reads ../shared (the developers'
# reference folder beside a checkout) or a path above the source tree. The
# reference data the tests compare with live in tests/data (its README.md
# says where each file came from). tools/contact_reference, which makes
# reference data from a CONTACT build, may say in prose where CONTACT came
# from; scripts/doc-check.sh names ../shared to forbid it in the documents.
# usage: check_self_contained.sh <source dir>
set -euo pipefail
cd "${1:?source dir}"
if git rev-parse --show-toplevel >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files --cached --others --exclude-standard)
else
  mapfile -t files < <(find . -type f -not -path './build*' -not -path './.git/*' | sed 's|^\./||')
fi
checked=()
for f in "${files[@]}"; do
  case "$f" in
    tests/*|python/*|matlab/*|examples/*|programs/*|bench/*|scripts/*|cmake/*|tools/*|CMakeLists.txt|*/CMakeLists.txt|run|.ci/*) ;;
    *) continue ;;
  esac
  case "$f" in
    tools/contact_reference/*|scripts/doc-check.sh|tests/install/check_self_contained.sh|tests/data/*) continue ;;
  esac
  [ -f "$f" ] && checked+=("$f")
done
if found=$(grep -n -I -E '\.\./shared|CREEPWORK_SHARED|CW_SHARED|PROJECT_SOURCE_DIR\}/\.\.' "${checked[@]}"); then
  echo "$found"
  echo "FAILED: the lines above reach outside the repository (../shared); the tests read their reference data from tests/data" >&2
  exit 1
fi
for f in kalker_cij.csv kalker1982_checks.csv contact_fastsim_dev.csv contact_exact_dev.csv \
         nonhertz/mbench_a22.csv nonhertz/dev/cases.csv README.md; do
  [ -s "tests/data/$f" ] || { echo "FAILED: tests/data/$f is missing" >&2; exit 1; }
done
echo "${#checked[@]} files of tests, programs, scripts and build read nothing outside the repository"
