#!/usr/bin/env bash
# The editor's frames at rest on heavy presets: opens each preset in the real editor under Xvfb
# (Mesa llvmpipe, 1280x800), leaves the view alone for SECONDS and reads `fraktal edit
# --frame-log`: frames drawn, the frame time p50/p95/max and the viewport's render time p95 of the
# frames after the first picture (the compile before it is not a frame at rest), the march steps
# a frame took (the last frame's), and the seconds from the first picture until the view settled.
# With two builds the presets run side by side, old then new, so that the machine's load falls on
# both alike. Each run has a shader cache of its own, empty: Mesa keeps llvmpipe's machine code
# there, so a run after another of the same preset would skip the translations its first frames
# pay (core/viewport/warm_up.hpp).
# Usage: bench/viewport/rest_frames.sh BUILD_DIR [OTHER_BUILD_DIR] [SECONDS] [PRESET...]
#        (default 20 s; kleinian, pseudo_kleinian, menger_carved_by_mandelbulbs, hybrid_kifs_menger, juliabulb)
set -euo pipefail
builds=("$1")
shift
if [ $# -gt 0 ] && [ -d "$1" ]; then builds+=("$1"); shift; fi
seconds=${1:-20}
[ $# -gt 0 ] && shift
root=$(cd "$(dirname "$0")/../.." && pwd)
presets=("$@")
[ ${#presets[@]} -gt 0 ] || presets=(kleinian pseudo_kleinian menger_carved_by_mandelbulbs hybrid_kifs_menger juliabulb)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| preset | build | frames in ${seconds} s | frame ms p50 | p95 | max | render ms p95 | steps/frame (last) | settled after |"
echo "|---|---|---|---|---|---|---|---|---|"
for name in "${presets[@]}"; do
  for build in "${builds[@]}"; do
    log="$work/$name.jsonl"
    rm -f "$log"
    rm -rf "$work/cache"
    HOME="$work" MESA_SHADER_CACHE_DIR="$work/cache" timeout "$((seconds + 30))" xvfb-run -a -s "-screen 0 1280x800x24" \
      "$build/app/fraktal" edit "$root/presets/$name.json" --frame-log "$log" --state-file "$work/state.json" \
      > /dev/null 2>&1 &
    pid=$!
    sleep "$seconds"
    pkill -f -- "--frame-log $log" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
    python3 - "$log" "$name" "$build" <<'PY'
import json, sys
lines = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
# Frames after the first that rendered the viewport (the compile and first picture come before).
first = next((i for i, l in enumerate(lines) if l["render_ms"] > 0), len(lines))
rest = lines[first + 1:]
def pct(v, p):
    v = sorted(v)
    return v[min(len(v) - 1, int(p * len(v)))] if v else float("nan")
frame = [l["frame_ms"] for l in rest]
render = [l["render_ms"] for l in rest]
steps = rest[-1].get("steps_per_frame", "-") if rest else "-"
settled_at = next((l["t"] for l in rest if l["settled"]), None)
settled = f"{settled_at - lines[first]['t']:.1f} s" if settled_at is not None else "no"
print(f"| {sys.argv[2]} | {sys.argv[3]} | {len(rest)} | {pct(frame, .5):.0f} | {pct(frame, .95):.0f} | "
      f"{max(frame) if frame else float('nan'):.0f} | {pct(render, .95):.0f} | {steps} | {settled} |")
PY
  done
done
