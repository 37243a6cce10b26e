#!/usr/bin/env bash
# Builds the libFuzzer harnesses (fuzz/) with clang, ASan and UBSan
# (float-cast-overflow included) into build-fuzz/, and runs each for a
# bounded time starting from the committed corpus in fuzz/corpus/. New
# inputs go to build-fuzz/corpus-*, not into the tree; a crash leaves its
# input in build-fuzz/ and makes the script fail.
#   scripts/fuzz.sh [--long] [HARNESS...]
#     harnesses: scene_parser off_reader command_line image_writer ply_reader
#     obj_reader stl_reader (default: all) and om_reader (by name only)
#     FUZZ_SECONDS per harness, default 30; --long: an hour each. Two
#     harnesses run at a time where there are two cores or more, each
#     harness's summary in build-fuzz/HARNESS.log
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-30}"
# Each libFuzzer process runs on one core.
parallel=$(( $(nproc) >= 2 ? 2 : 1 ))
if [ "${1:-}" = --long ]; then
  seconds=3600
  shift
fi
harnesses=("$@")
# om_reader is run by name only: OM files are refused after their header's
# check (OpenMesh's OM reader is not safe on a damaged file; README).
[ ${#harnesses[@]} -gt 0 ] ||
  harnesses=(scene_parser off_reader command_line image_writer ply_reader obj_reader stl_reader)

scripts/install-packages.sh clang libclang-rt-14-dev
# -O1 with line tables only, as libFuzzer's documentation builds: a
# finding's stack trace keeps file and line, and the build is quicker.
flags="-O1 -gline-tables-only -DNDEBUG"
CC=clang CXX=clang++ cmake -S fuzz -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_FLAGS_RELWITHDEBINFO="$flags" -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="$flags" >/dev/null
cmake --build build-fuzz -j "$(nproc)"

declare -A corpus=([scene_parser]=scene [off_reader]=off [command_line]=command_line
                   [image_writer]=image_writer)
# The OFF harness pads each input by a parse chunk itself; the command line
# harness's tool prints a line per render, kept out of the log.
declare -A extra=([scene_parser]="-dict=fuzz/scene.dict" [off_reader]=""
                  [command_line]="-dict=fuzz/command_line.dict -close_fd_mask=3"
                  [image_writer]="")
for f in ply obj stl om; do corpus[${f}_reader]=$f; extra[${f}_reader]=""; done

# Runs one harness; prints libFuzzer's last lines and fails on a finding.
run() {
  local h=$1 work="build-fuzz/corpus-$1"
  mkdir -p "$work"
  echo "== fuzzing $h for ${seconds}s"
  # Leaks are checked; a 10 s per-input timeout and a 2 GB memory cap
  # catch hangs and runaway allocation.
  local status=0
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    "build-fuzz/fuzz_$h" "$work" "fuzz/corpus/${corpus[$h]}" ${extra[$h]} \
    -max_total_time="$seconds" -max_len=4096 -timeout=10 -rss_limit_mb=2048 \
    -artifact_prefix="build-fuzz/$h-" -print_final_stats=1 >"build-fuzz/$h.log" 2>&1 || status=$?
  grep -E "^#|ERROR|SUMMARY|stat::number_of_executed_units|Done" "build-fuzz/$h.log" | tail -n 5
  return $status
}

failed=0
for ((i = 0; i < ${#harnesses[@]}; i += parallel)); do
  pids=()
  for h in "${harnesses[@]:i:parallel}"; do
    run "$h" &
    pids+=($!)
  done
  for pid in "${pids[@]}"; do wait "$pid" || failed=1; done
done
exit $failed
