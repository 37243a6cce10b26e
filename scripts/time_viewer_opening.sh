#!/usr/bin/env bash
# Opening a scene in the viewer's real window (under Xvfb when there is no
# display) against a whole `raytrace` run of it, in the same run: rounds
# of one raytrace run and one window opening, in turn. Prints per round the
# raytrace run's wall time, the viewer's first and exact image (from its
# --frame-log, counted from the opening), their ratios, and the longest
# frame while the scene opened and rendered, with the UI thread's own
# processor time in it (the rest it waited for a core or for GL), and
# that frame's whole log line (the kernel's share, page faults, waits and
# preemptions). Before its first frame the window draws once, unseen, to
# have the shaders compiled: shown_ms is how long that took.
# With COLD_SHADER_CACHE=1 every window starts with an empty shader cache,
# as on a fresh machine.
# Usage: scripts/time_viewer_opening.sh SCENE.sce [ROUNDS] [-- VIEWER ARGS]
set -euo pipefail
cd "$(dirname "$0")/.."
scene=$1
rounds=${2:-3}
shift $(( $# >= 2 ? 2 : 1 ))
[ "${1:-}" != -- ] || shift
bin=build/bin
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
run_window() {
  if [ "${COLD_SHADER_CACHE:-0}" = 1 ]; then
    rm -rf "$work/cache" && mkdir "$work/cache"
    export XDG_CACHE_HOME=$work/cache
  fi
  if [ -n "${DISPLAY:-}" ]; then
    "$bin/viewer" "$@"
  else
    xvfb-run -a -s "-screen 0 1280x720x24" "$bin/viewer" "$@"
  fi
}
printf '%-5s %12s %9s %12s %12s %8s %8s %12s %9s %7s\n' round raytrace_ms shown_ms first_ms \
  exact_ms first/rt exact/rt longest_ms its_cpu frames
for ((r = 1; r <= rounds; ++r)); do
  start=$(date +%s.%N)
  "$bin/raytrace" "$scene" "$work/out.png" > /dev/null
  rt=$(echo "($(date +%s.%N) - $start) * 1000" | bc)
  run_window --size 1280x720 --no-default-dirs --frame-log --quit-when-done "$@" "$scene" \
    2> "$work/frames.log" > /dev/null
  awk -v rt="$rt" -v r="$r" '
    /^frame / {
      sub("ms:", "", $2); n++
      if ($2 > longest) {
        longest = $2
        line = $0
        for (i = 1; i <= NF; ++i) if ($i == "cpu") { cpu = $(i + 1); sub(",", "", cpu) }
      }
    }
    /^window shown after/ { shown = $4 }
    /^render .*: first image/ && !done {
      for (i = 1; i <= NF; ++i) {
        if ($i == "first" && $(i + 1) == "image") first = $(i + 2)
        if ($i == "exact" && $(i + 1) == "image") exact = $(i + 2)
      }
      done = 1
    }
    END {
      printf "%-5d %12.1f %9.1f %12.1f %12.1f %8.3f %8.3f %12.1f %9.1f %7d\n", r, rt, shown, first,
             exact, first / rt, exact / rt, longest, cpu, n
      printf "      longest: %s\n", line
    }' "$work/frames.log"
done
