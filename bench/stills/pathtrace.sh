#!/usr/bin/env bash
# Path-traced Mandelbulb: the time for fraktal's GL path tracer (`--mode path`) to reach 35 dB
# mean-image PSNR against its own REF_SPP-sample converged image (bench/stills/pathtrace.cpp;
# with and without the denoiser), and mandelbulber2's Monte Carlo global-illumination still of the
# same scene (bench/stills/mandelbulb.fract with DOF_monte_carlo, DOF_MC_global_illumination and
# MC soft shadows on, no blur, MB_SPP samples), timed side by side in one run.
# The lit scene: presets/mandelbulb.json with a sun-sized directional light, a rect area light and
# presets/env/sky.exr, 3 bounces.
# Usage: bench/stills/pathtrace.sh BUILD_DIR [WxH] [REF_SPP] [MB_SPP]   (default 1280x720 4096 64;
# on a slow or shared machine measure smaller, e.g. 160x90 1024 64, and say so)
set -euo pipefail
build="${1:-build}"; size="${2:-1280x720}"; ref="${3:-4096}"; mbspp="${4:-64}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
source "$root/bench/stills/peer.sh"
cmake --build "$root/$build" --target bench_pathtrace > /dev/null
cp "$root/$build/bench/bench_pathtrace" "$tmp/pathtrace"
python3 - "$root/presets/mandelbulb.json" "$tmp/lit.json" "$root/presets/env/sky.exr" <<'PY'
import json, sys
p = json.load(open(sys.argv[1]))
p["lights"] = [
    {"type": "directional", "direction": [0.5, 0.8, 0.4], "intensity": 2.0, "size": 0.27},
    {"type": "rect", "position": [0, 2.2, 1.2], "normal": [0, -0.8, -0.5], "up": [0, 0, 1],
     "size": 1.5, "height": 1.0, "intensity": 1.5}]
p["environment"] = {"map": sys.argv[3], "intensity": 0.5}
p["pathTrace"] = {"bounces": 3}
json.dump(p, open(sys.argv[2], "w"), indent=1)
PY
t0=$(date +%s.%N)
"$tmp/pathtrace" "$tmp/lit.json" "$size" "$ref" --denoise | tee "$tmp/pt.log"
t1=$(date +%s.%N)
if [[ $peer == 1 ]]; then
  # The Monte Carlo keys go into the [main_parameters] section.
  mc="DOF_enabled true;\nDOF_monte_carlo true;\nDOF_MC_global_illumination true;\nMC_soft_shadows_enable true;\nDOF_radius 0;\nDOF_samples $mbspp;\nDOF_max_noise 0;"
  sed "s/^\[main_parameters\]/[main_parameters]\n$mc/" "$root/bench/stills/mandelbulb.fract" > "$tmp/mb.fract"
  t2=$(date +%s.%N)
  HOME="$tmp" mandelbulber2 -n -f png -r "$size" -o "$tmp/mb" "$tmp/mb.fract" > "$tmp/mb.log" 2>&1
  t3=$(date +%s.%N)
fi
reach=$(grep "^35 dB" "$tmp/pt.log")
echo
echo "| renderer | size | what | seconds |"
echo "|---|---|---|---|"
echo "| fraktal --mode path | $size | $reach | (whole run with the reference: $(echo "$t1 - $t0" | bc -l | xargs printf %.1f)) |"
if [[ $peer == 1 ]]; then
  echo "| mandelbulber2 Monte Carlo GI | $size | $mbspp samples | $(echo "$t3 - $t2" | bc -l | xargs printf %.1f) |"
else
  echo "| mandelbulber2 Monte Carlo GI | $size | skipped: not installed | - |"
fi
