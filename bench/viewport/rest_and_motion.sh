#!/usr/bin/env bash
# The editor's frame times at rest and in motion on heavy scenes: opens each preset in the real
# editor under Xvfb (Mesa llvmpipe, 1280x800), leaves it alone until the view settles (at most
# SETTLE_MAX seconds), then orbits the camera with a left drag through the X server (xdotool, 60
# moves over about 6 s). From `fraktal edit --frame-log`: the UI frame time p50/p95/max at rest
# (the frames after the first picture until the drag) and in motion (the frames during the drag),
# the most slices a frame at rest refined one of, and the seconds from the first picture until
# the view settled; the main thread's render time (render_ms) of the first picture after opening,
# at its p95 and most at rest and in motion, and in the first frame of motion after rest (onto the
# smaller grid). A PRESET is a name in presets/ or a path; `kleinian_x3` is kleinian.json with
# its group block three times. With two builds each scene runs old then new, so that the machine's
# load falls on both alike. Each run starts with an empty shader cache.
# Usage: [KEEP_LOGS=DIR] bench/viewport/rest_and_motion.sh BUILD_DIR [OTHER_BUILD_DIR] [SETTLE_MAX] [PRESET...]
#        (default 90 s; kleinian pseudo_kleinian menger_field_depth_of_field hybrid_amazing_surf_box
#        inverted_menger kleinian_x3)
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ "${1:-}" != --inner ]; then exec xvfb-run -a -s "-screen 0 1280x800x24" "$0" --inner "$@"; fi
shift
builds=("$1")
shift
if [ $# -gt 0 ] && [ -d "$1" ]; then builds+=("$1"); shift; fi
settle_max=${1:-90}
[ $# -gt 0 ] && shift
presets=("$@")
[ ${#presets[@]} -gt 0 ] ||
  presets=(kleinian pseudo_kleinian menger_field_depth_of_field hybrid_amazing_surf_box inverted_menger kleinian_x3)
work=$(mktemp -d)
pid=
trap '[ -z "$pid" ] || kill "$pid" 2>/dev/null || true; rm -rf "$work"' EXIT
jq '.name = "Three Kleinian nodes" | .formula.nodes = [.formula.nodes[0], .formula.nodes[0], .formula.nodes[0], .formula.nodes[1]]' \
  "$root/presets/kleinian.json" > "$work/kleinian_x3.json"
echo "| scene | build | first picture render | rest frames | rest ms p50 | p95 | max | render p95 | render max | slices (most) | settled after | motion frames | motion ms p50 | p95 | max | render p95 | render max | first move render |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
for name in "${presets[@]}"; do
  case $name in
    kleinian_x3) file="$work/kleinian_x3.json" ;;
    */*) file=$name ;;
    *) file="$root/presets/$name.json" ;;
  esac
  for build in "${builds[@]}"; do
    log="$work/frames.jsonl"
    rm -f "$log" "$work/state.json"
    mkdir -p "$work/home"
    # A shader cache of its own, empty (as in rest_frames.sh): Mesa keeps llvmpipe's machine code
    # there, and a run after another of the same scene would skip the translations its first
    # frames pay (core/viewport/warm_up.hpp).
    rm -rf "$work/cache"
    HOME="$work/home" XDG_CONFIG_HOME="$work/home/config" MESA_SHADER_CACHE_DIR="$work/cache" "$build/app/fraktal" edit "$file" --frame-log "$log" \
      --state-file "$work/state.json" > /dev/null 2>&1 &
    pid=$!
    # Until the view settles (a frame logged settled) or settle_max seconds after the first line.
    for _ in $(seq 1 $((settle_max * 4 + 240))); do
      grep -q '"settled":true' "$log" 2>/dev/null && break
      sleep 0.25
    done
    rest_end=$(wc -l < "$log")
    window=$(xdotool search --onlyvisible --name fraktal | head -1)
    read -r cx cy < <(jq -r '"\(.viewport[0] + .viewport[2] / 2 | floor) \(.viewport[1] + .viewport[3] / 2 | floor)"' \
      "$work/state.json")
    xdotool mousemove --window "$window" "$cx" "$cy"
    sleep 0.3
    xdotool mousedown 1
    for i in $(seq 1 60); do
      xdotool mousemove --window "$window" $((cx + 4 * i)) $((cy + i))
      sleep 0.1
    done
    xdotool mouseup 1
    motion_end=$(wc -l < "$log")
    # KEEP_LOGS=DIR keeps each run's frame log there (scene-build.jsonl), to look at its frames.
    [ -z "${KEEP_LOGS:-}" ] || { mkdir -p "$KEEP_LOGS"; cp "$log" "$KEEP_LOGS/$name-$(echo "$build" | tr / _).jsonl"; }
    kill "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    pid=
    python3 - "$log" "$name" "$build" "$rest_end" "$motion_end" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
rest_end, motion_end = int(sys.argv[4]), int(sys.argv[5])
first = next((i for i, l in enumerate(lines) if l["render_ms"] > 0), len(lines))
rest = lines[first + 1:rest_end]
# Motion from the drag's first moved frame: the frames before it are the settled view's idle
# waits for input (the editor sleeps until an event once settled), not frames that took long.
drag = lines[rest_end:motion_end]
moved = next((i for i, l in enumerate(drag) if l["action"] in ("reproject", "hold") or l["width"] != drag[0]["width"]),
             len(drag))
motion = drag[moved:]
def pct(v, p):
    v = sorted(v)
    return f"{v[min(len(v) - 1, int(p * len(v)))]:.0f}" if v else "-"
def most(v):
    return f"{max(v):.0f}" if v else "-"
rf = [l["frame_ms"] for l in rest]
mf = [l["frame_ms"] for l in motion]
rr = [l["render_ms"] for l in rest]
mr = [l["render_ms"] for l in motion]
# The first frame of motion after rest: the first of the drag whose grid is not the rest grid's.
first_move = next((l["render_ms"] for l in motion if rest and l["width"] != rest[-1]["width"]), None)
slices = max((l.get("slices", 1) for l in rest), default=1)
settled_at = next((l["t"] for l in rest if l["settled"]), None)
settled = f"{settled_at - lines[first]['t']:.1f} s" if settled_at is not None and first < len(lines) else "no"
first_move = f"{first_move:.0f}" if first_move is not None else "-"
opening = f"{lines[first]['render_ms']:.0f}" if first < len(lines) else "-"
print(f"| {sys.argv[2]} | {sys.argv[3]} | {opening} | {len(rest)} | {pct(rf, .5)} | {pct(rf, .95)} | {most(rf)} | "
      f"{pct(rr, .95)} | {most(rr)} | {slices} | {settled} | {len(mf)} | {pct(mf, .5)} | {pct(mf, .95)} | {most(mf)} | "
      f"{pct(mr, .95)} | {most(mr)} | {first_move} |")
PY
  done
done
