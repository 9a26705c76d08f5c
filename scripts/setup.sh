#!/usr/bin/env bash
# Installs the Debian 12 packages sqdem needs (when missing), configures a Release build in
# ./build and builds it. Used by both quick-start commands in README.md and by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(g++ make cmake libeigen3-dev libboost-dev libfcl-dev nlohmann-json3-dev
          libgtest-dev libbenchmark-dev gnuplot-nox libyaml-cpp-dev libcgal-dev libvtk9-dev libopenmpi-dev openmpi-bin
          xvfb xauth python3-dev pybind11-dev python3-numpy python3-pytest python3-matplotlib)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}"
  SUDO=$([ "$(id -u)" -eq 0 ] && echo "" || echo sudo)
  $SUDO apt-get update
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y --no-install-recommends "${missing[@]}"
fi

cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j2
