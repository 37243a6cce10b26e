#!/usr/bin/env bash
# The main job: set up, build, and render the project's own scenes into
# results/ (colour images and bounding-box debug images).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/bin/raytrace --all scenes results
build/bin/debug_aabb --all scenes results
