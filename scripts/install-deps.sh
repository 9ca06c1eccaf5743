#!/usr/bin/env bash
# Installs the Debian packages creepwork needs, if any is missing. As root it
# uses apt-get; otherwise it lists what to install and fails.
set -euo pipefail

packages=(cmake g++ gfortran make pkg-config libeigen3-dev libcmocka-dev gnuplot-nox
          clang-14 libclang-rt-14-dev libomp-14-dev valgrind)

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
export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
