#!/usr/bin/env bash
# The editor's orbit drag on the idle machine and beside a 2-job build of this project (ccache off,
# a fresh build folder), in three configurations, each RUNS times, interleaved so that the load
# drifts over them alike:
#   "1/4, whole UI": the lowest motion scale a quarter, every window drawn every frame (as before);
#   "1/8, whole UI": the lowest motion scale an eighth (the default);
#   "1/8, kept UI":  and the side column drawn from a kept copy during the drag (the default,
#                    app/editor/viewport/ui_redraw.hpp).
# Prints one table row per run: load average, orbit frame p50/p95, the parameter drag's p95, the
# internal scale.
# Usage: bench/viewport/editor_load.sh BUILD_DIR [RUNS] [PRESET]   (default 2 runs, mandelbulb)
set -euo pipefail
build=${1:?build dir}
runs=${2:-2}
preset=${3:-presets/mandelbulb.json}
root=$(cd "$(dirname "$0")/../.." && pwd)
work=$(mktemp -d)
load_pid=
cleanup() {
  [ -n "$load_pid" ] && kill -- -"$load_pid" 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT

row() {  # $1 machine, $2 configuration
  local args= preset_used=$preset
  case $2 in
    "1/4, whole UI") args=--full-ui-redraw preset_used=$quarter ;;
    "1/8, whole UI") args=--full-ui-redraw ;;
  esac
  local json
  json=$(FRAKTAL_EDIT_ARGS=$args "$root/bench/viewport/editor_run.sh" "$build" "$preset_used" 1280x720 |
    sed -n '/^{/,/^}/p')
  python3 - "$1" "$2" "$(cut -d' ' -f1 /proc/loadavg)" "$json" <<'PY'
import json, sys
r = json.loads(sys.argv[4])
print(f"| {sys.argv[1]} | {sys.argv[2]} | {sys.argv[3]} | {r['frame_ms_p50']:.1f} | {r['frame_ms_p95']:.1f} | "
      f"{r['param_frame_ms_p95']:.1f} | {r['scale_p50']} |")
PY
}
configs=("1/4, whole UI" "1/8, whole UI" "1/8, kept UI")
# The preset with the editor's lowest motion scale at a quarter.
quarter="$work/quarter.json"
jq '.editor.view.motionMinScale = 0.25' "$preset" > "$quarter"

echo "| machine | configuration | load average | orbit frame p50 (ms) | orbit frame p95 (ms) | parameter drag p95 (ms) | internal scale p50 |"
echo "|---|---|---|---|---|---|---|"
for _ in $(seq 1 "$runs"); do
  for c in "${configs[@]}"; do row idle "$c"; done
done
# The load: a 2-job build of the project from scratch, in its own process group.
setsid bash -c "cmake -S '$root' -B '$work/load' -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null &&
  CCACHE_DISABLE=1 cmake --build '$work/load' --parallel 2 >/dev/null 2>&1" &
load_pid=$!
sleep 20  # the compilers running
for _ in $(seq 1 "$runs"); do
  for c in "${configs[@]}"; do row "2-job build" "$c"; done
done
