#!/usr/bin/env bash
# Orbiting a scene in the viewer's real window (under Xvfb when there is no
# display): opens SCENE at 1280x720, waits for its exact image, then drags
# the camera with xdotool for about DRAG_SECONDS. From the viewer's
# --frame-log it prints per round how many new camera images reached the
# screen per second while dragging, the longest wait between two of them,
# and the longest frame.
# Usage: scripts/time_viewer_orbit.sh SCENE.sce [ROUNDS] [DRAG_SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1
rounds=${2:-3}
drag_seconds=${3:-2}
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1280x720x24" "$0" "$@"
fi
work=$(mktemp -d)
viewer=
cleanup() {
  [ -z "$viewer" ] || kill "$viewer" 2> /dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
printf '%-5s %14s %16s %16s %7s\n' round images_per_s longest_gap_ms longest_frame_ms images
for ((r = 1; r <= rounds; ++r)); do
  log=$work/frames$r.log
  build/bin/viewer --size 1280x720 --no-default-dirs --frame-log "$scene" 2> "$log" > /dev/null &
  viewer=$!
  for ((wait = 0; wait < 600; ++wait)); do
    ! grep -qs '^render .*exact image' "$log" || break
    sleep 0.1
  done
  # The image's middle, in the window at 0,0; a step every 10 ms, all in
  # one xdotool process: where starting a process is slow, a process a
  # step would set the pace instead of the viewer.
  drag=(mousemove 575 370 mousedown 1)
  steps=$((drag_seconds * 100))
  for ((i = 1; i <= steps; ++i)); do
    drag+=(sleep 0.01 mousemove $((575 + (i % 200) - 100)) $((370 + (i % 40) - 20)))
  done
  xdotool "${drag[@]}" mouseup 1
  sleep 0.5
  kill "$viewer"
  wait "$viewer" 2> /dev/null || true
  viewer=
  [ -z "${KEEP_LOGS:-}" ] || cp "$log" "$KEEP_LOGS$r.log"
  awk -v r="$r" '
    /^render .*exact image/ { opened = 1; next }
    opened && /^frame / {
      sub("ms:", "", $2); if ($2 > longest) longest = $2
      for (i = 1; i <= NF; ++i) if ($i == "at") { at = $(i + 1); sub(",", "", at) }
      if ($0 ~ /shows a first image/) {
        if (n > 0 && at - last > gap) gap = at - last
        if (n == 0) first = at
        last = at; n++
      }
    }
    END {
      printf "%-5d %14.1f %16.1f %16.1f %7d\n", r, (n > 1 ? (n - 1) * 1000 / (last - first) : 0),
             gap, longest, n
    }' "$log"
done
