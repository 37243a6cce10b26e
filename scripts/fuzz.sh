#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/) with clang, ASan and UBSan into
# build-fuzz/, and runs each for a bounded time (FUZZ_SECONDS, default 30)
# starting from the committed corpus in fuzz/corpus/. New inputs go to
# build-fuzz/corpus-*, not into the tree; a crash leaves its input in
# build-fuzz/ and makes the script fail.
#   scripts/fuzz.sh [HARNESS...]   harnesses: scene_parser off_reader
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-30}"
harnesses=("$@")
[ ${#harnesses[@]} -gt 0 ] || harnesses=(scene_parser off_reader)

scripts/install-packages.sh clang libclang-rt-14-dev
CC=clang CXX=clang++ cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build build-fuzz -j "$(nproc)"

declare -A corpus=([scene_parser]=scene [off_reader]=off)
declare -A extra=([scene_parser]="-dict=fuzz/scene.dict" [off_reader]="")
for h in "${harnesses[@]}"; do
  work="build-fuzz/corpus-$h"
  mkdir -p "$work"
  echo "== fuzzing $h for ${seconds}s"
  # Leaks are checked; a 10 s per-input timeout and a 2 GB memory cap
  # catch hangs and runaway allocation.
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "build-fuzz/fuzz_$h" "$work" "fuzz/corpus/${corpus[$h]}" ${extra[$h]} \
    -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="build-fuzz/$h-" -print_final_stats=1 2>&1 | grep -E "^#|ERROR|SUMMARY|stat::number_of_executed_units|Done" | tail -n 5
  test "${PIPESTATUS[0]}" -eq 0
done
