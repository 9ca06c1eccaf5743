#!/usr/bin/env bash
# Installs the Debian packages creepwork needs, if any is missing. As root it
# uses apt-get; otherwise it lists what to install and fails.
#   install-deps.sh demo   what ./run demo needs: the library, the CLI, gnuplot
#   install-deps.sh all    everything ./run test needs (default): also
#                          gfortran, cmocka, clang for fuzzing and TSan,
#                          valgrind, Open MPI for creepwork campaign and
#                          its tests (the demo builds without it), numpy,
#                          pytest, venv, setuptools and wheel for the Python
#                          package and its tests, Octave for the MEX,
#                          ccache (the recipes' builds reuse the Release
#                          build's objects)
#   install-deps.sh python what the Python package needs (doc/python.md)
#   install-deps.sh octave what the Octave interface needs (doc/octave.md)
set -euo pipefail

demo=(cmake g++ make libeigen3-dev gnuplot-nox)
library=(cmake g++ make libeigen3-dev python3)
# numpy at run time; venv, setuptools and wheel for doc/python.md's offline pip route
python=(python3-numpy python3-venv python3-setuptools python3-wheel)
octave=(octave liboctave-dev)
all=("${demo[@]}" ccache gfortran pkg-config libcmocka-dev clang-14 libclang-rt-14-dev libomp-14-dev
     valgrind libopenmpi-dev openmpi-bin "${python[@]}" python3-pytest "${octave[@]}")
case "${1:-all}" in
  demo) packages=("${demo[@]}") ;;
  all) packages=("${all[@]}") ;;
  python) packages=("${library[@]}" "${python[@]}") ;;
  octave) packages=("${library[@]}" "${octave[@]}") ;;
  *) echo "usage: install-deps.sh [demo|all|python|octave]" >&2; exit 2 ;;
esac

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

if [ "$(id -u)" -ne 0 ]; then
  echo "missing Debian packages: ${missing[*]}" >&2
  echo "install them with: sudo apt-get install -y ${missing[*]}" >&2
  exit 1
fi
echo "installing Debian packages: ${missing[*]} ..."
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq >/dev/null
apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
