#!/usr/bin/env bash
# Regenerates our scenes' meshes and our reference renders in
# expected_results/. Run after a deliberate change to the rendering model or
# to a scene, then look at every image before committing.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
build/bin/make_scenes scenes
build/bin/raytrace --all scenes expected_results
