#!/usr/bin/env bash
# Installs the Debian packages meshtrace needs (only those missing) and
# builds the project into build/. Safe to run again: both steps are
# incremental. Usage: scripts/setup.sh [extra cmake arguments]
#                    scripts/setup.sh --packages-only
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(
  # toolchain
  cmake g++ ninja-build pkg-config
  # core
  libglm-dev libtbb-dev libstb-dev libjpeg-dev libpng-dev libcli11-dev libopenexr-dev
  # raytrace --report's plots
  gnuplot-nox
  # tests and benchmarks (openexr: exrheader, to look at EXR outputs; parallel:
  # the shard test runs raytrace --all --shard through GNU parallel)
  libgtest-dev libbenchmark-dev openexr parallel
  # the viewer: window, UI, offscreen GL, the OpenMesh cross-check, and its
  # headless snapshot and real-window tests
  libglfw3-dev libimgui-dev libosmesa6-dev libgl1-mesa-dri libopenmesh-dev
  xvfb xauth xdotool
)

scripts/install-packages.sh "${packages[@]}"
[ "${1:-}" != --packages-only ] || exit 0

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "$@"
cmake --build build
