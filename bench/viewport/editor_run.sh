#!/usr/bin/env bash
# The viewport in the real editor window: starts `fraktal edit` under Xvfb (Mesa llvmpipe), waits
# until the view has settled, drives an orbit drag through the X server with xdotool (the same
# GLFW callbacks as a person's mouse), lets go, waits 2 s and takes a screenshot; then opens the
# camera the orbit ended at in a fresh editor and lets it settle for the reference. Prints JSON:
# frame time p50/p95 during the drag (from `fraktal edit --frame-log`), the internal scale
# dynamic resolution chose, and the PSNR of the viewport 2 s after the drag against the fresh
# settled render (the stats overlay's corner and the status line left out).
# Usage: bench/viewport/editor_run.sh BUILD_DIR [PRESET] [WxH]   (default mandelbulb, 1280x720)
# FRAKTAL_EDIT_ARGS adds options to the measured editor (e.g. --full-ui-redraw).
set -euo pipefail
if [ "${1:-}" = "--inner" ]; then
  shift
  fraktal=$1 preset=$2 w=$3 h=$4 work=$5
  # Waits (up to $2 s) until the frame log $1 has a settled frame after line $3.
  wait_settled() {
    for _ in $(seq 1 $(( $2 * 4 ))); do
      if tail -n +"$(( $3 + 1 ))" "$1" 2>/dev/null | grep -q '"settled":true'; then return 0; fi
      sleep 0.25
    done
    echo "editor_run: the view did not settle in $2 s ($1)" >&2; return 1
  }
  # shellcheck disable=SC2086  # FRAKTAL_EDIT_ARGS: extra options, word-split (e.g. --full-ui-redraw)
  "$fraktal" edit "$preset" --width "$w" --height "$h" --frame-log "$work/moving.jsonl" \
    --state-file "$work/state.json" ${FRAKTAL_EDIT_ARGS:-} > "$work/editor.out" 2>&1 &
  pid=$!
  trap 'kill $pid 2>/dev/null || true' EXIT
  wait_settled "$work/moving.jsonl" 180 0
  read -r vx vy vw vh < <(tail -n 1 "$work/moving.jsonl" | python3 -c '
import json, sys; v = json.loads(sys.stdin.read())["viewport"]; print(*[int(x) for x in v])')
  cx=$(( vx + vw / 2 )); cy=$(( vy + vh / 2 ))
  start=$(wc -l < "$work/moving.jsonl")
  xdotool mousemove "$cx" "$cy"; sleep 0.2
  xdotool mousedown 1
  # An orbit: 3 s of drag, 4 px every 20 ms, right then up.
  for i in $(seq 1 150); do
    if [ "$i" -le 100 ]; then xdotool mousemove_relative -- 4 0; else xdotool mousemove_relative -- 0 -4; fi
    sleep 0.02
  done
  xdotool mouseup 1
  stop=$(wc -l < "$work/moving.jsonl")
  sleep 2
  import -window root "$work/rest.png"
  # A parameter drag: the selected node's first slider (the power of the Mandelbulb), 2 s of drag,
  # 1 px every 20 ms to the right, from the rectangle the state file gives.
  wait_settled "$work/moving.jsonl" 180 "$stop"
  read -r px py < <(python3 -c '
import json, sys; r = json.load(open(sys.argv[1]))["paramWidgets"][0]["rect"]; print(int(r[0] + r[2] / 2), int(r[1] + r[3] / 2))' "$work/state.json")
  param_start=$(wc -l < "$work/moving.jsonl")
  xdotool mousemove "$px" "$py"; sleep 0.2
  xdotool mousedown 1
  for i in $(seq 1 100); do xdotool mousemove_relative -- 1 0; sleep 0.02; done
  xdotool mouseup 1
  param_stop=$(wc -l < "$work/moving.jsonl")
  kill $pid; wait $pid 2>/dev/null || true
  trap - EXIT
  # The fresh render: the camera the orbit ended at, in a new editor, settled.
  python3 - "$preset" "$work/moving.jsonl" "$work/fresh.json" <<'PY'
import json, sys
preset = json.load(open(sys.argv[1]))
last = [json.loads(l) for l in open(sys.argv[2])][-1]["camera"]
preset["camera"] = {"position": last["position"], "target": last["target"], "up": last["up"], "fovY": last["fovY"]}
json.dump(preset, open(sys.argv[3], "w"))
PY
  "$fraktal" edit "$work/fresh.json" --width "$w" --height "$h" --frame-log "$work/fresh.jsonl" \
    > "$work/fresh.out" 2>&1 &
  pid=$!
  trap 'kill $pid 2>/dev/null || true' EXIT
  wait_settled "$work/fresh.jsonl" 300 0
  sleep 0.5
  import -window root "$work/fresh.png"
  kill $pid; wait $pid 2>/dev/null || true
  trap - EXIT
  # Below the stats overlay, above the status line.
  crop="${vw}x$(( vh - 190 ))+${vx}+$(( vy + 140 ))"
  convert "$work/rest.png" -crop "$crop" +repage "$work/rest_crop.png"
  convert "$work/fresh.png" -crop "$crop" +repage "$work/fresh_crop.png"
  psnr=$(compare -metric PSNR "$work/rest_crop.png" "$work/fresh_crop.png" null: 2>&1 || true)
  python3 - "$work/moving.jsonl" "$start" "$stop" "$psnr" "$w" "$h" "$param_start" "$param_stop" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1])]
start, stop = int(sys.argv[2]), int(sys.argv[3])
param = lines[int(sys.argv[7]) + 1:int(sys.argv[8])]
param_ms = sorted(f["frame_ms"] for f in param)
param_scales = sorted(f["scale"] for f in param)
drag = lines[start + 1:stop]  # the first frame's time includes the wait before the drag
ms = sorted(f["frame_ms"] for f in drag)
scales = sorted(f["scale"] for f in drag if f["action"] == "reproject")
def pct(v, p): return v[min(len(v) - 1, int(p * len(v)))] if v else None
psnr = sys.argv[4].split()[0]
result = {
    "window": f"{sys.argv[5]}x{sys.argv[6]}",
    "viewport": lines[-1]["viewport"],
    "drag_frames": len(drag),
    "frame_ms_p50": pct(ms, 0.5), "frame_ms_p95": pct(ms, 0.95), "frame_ms_max": ms[-1] if ms else None,
    # The viewport's own part of a frame (the rest: panels, display, swap under Xvfb).
    "viewport_ms_p50": pct(sorted(f["render_ms"] for f in drag), 0.5),
    # Frames drawn from the kept copy of the window (app/editor/viewport/ui_redraw.hpp) and their p50.
    "ui_cached_frames": sum(f.get("ui") == "cached" for f in drag),
    "cached_frame_ms_p50": pct(sorted(f["frame_ms"] for f in drag if f.get("ui") == "cached"), 0.5),
    "whole_frame_ms_p50": pct(sorted(f["frame_ms"] for f in drag if f.get("ui") != "cached"), 0.5),
    "scale_min": scales[0] if scales else None, "scale_p50": pct(scales, 0.5),
    "internal_size_p50": [f"{f['width']}x{f['height']}" for f in drag if f["scale"] == pct(scales, 0.5)][:1],
    "psnr_2s_after_stop_db": float(psnr) if psnr.replace('.', '', 1).isdigit() else psnr,
    # The parameter drag (every frame a new value: the march restarts at the chosen scale).
    "param_drag_frames": len(param),
    "param_frame_ms_p50": pct(param_ms, 0.5), "param_frame_ms_p95": pct(param_ms, 0.95),
    "param_scale_p50": pct(param_scales, 0.5),
}
print(json.dumps(result, indent=1))
# The same as a Markdown table, for bench/run.sh.
print("\n| measure | value |\n|---|---|")
for key, value in result.items(): print(f"| {key} | {value} |")
PY
  exit 0
fi
build=${1:?build dir}
preset=${2:-presets/mandelbulb.json}
size=${3:-1280x720}
w=${size%x*}; h=${size#*x}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# A private HOME and config folder: no personal editor.ini, recent list or autosave.
HOME="$work" XDG_CONFIG_HOME="$work/config" xvfb-run -a -s "-screen 0 ${w}x${h}x24" "$0" --inner "$(realpath "$build/app/fraktal")" \
  "$(realpath "$preset")" "$w" "$h" "$work"
