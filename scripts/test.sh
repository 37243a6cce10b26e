#!/usr/bin/env bash
# Set up, build, and run every test. Tests against the seed reference images
# read ../shared/seed and skip, saying so, when it is absent.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh
ctest --test-dir build --output-on-failure -j "$(nproc)"
