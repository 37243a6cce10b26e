#!/usr/bin/env bash
# The main job: set up and build, then open the viewer where a display
# exists; without one, render our scenes into results/ (colour images and
# bounding-box debug images).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
if [ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]; then
  exec build/bin/viewer "$@"
fi
build/bin/raytrace --all scenes results
build/bin/debug_aabb --all scenes results
