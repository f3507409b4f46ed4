#!/usr/bin/env bash
# 2D benchmark, side by side in one run on this machine:
#  1. `fraktal render` of every 2D preset at 1920x1080 and 3840x2160, SPP samples per pixel:
#     wall time end to end (start-up, GL, EXR and PNG writing) and Msamples/s;
#  2. the renderer alone (bench/plane/plane_bench.cpp, linked against BUILD_DIR's core): GL in
#     double vs single precision, the one-thread CPU reference (double), iterations per sample.
# Usage: bench/plane/run.sh BUILD_DIR [SPP] [GL_WxH] [CPU_WxH]
set -euo pipefail
build="${1:-build}"; spp="${2:-2}"; glsize="${3:-640x360}"; cpusize="${4:-320x180}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
fraktal="$root/$build/app/fraktal"

echo "## fraktal render, $spp spp ($(nproc) cores)"
echo
echo "| preset | size | wall s | Msamples/s |"
echo "|---|---|---|---|"
for preset in "$root"/presets/2d/*.json; do
  name=$(basename "$preset" .json)
  for size in 1920x1080 3840x2160; do
    t0=$(date +%s.%N)
    "$fraktal" render "$preset" -o "$tmp/$name.exr" --png "$tmp/$name.png" --size "$size" --spp "$spp" -q
    t1=$(date +%s.%N)
    px=$(echo "$size" | tr x '*' | bc)
    echo "| $name | $size | $(echo "$t1 - $t0" | bc -l | xargs printf %.2f) | $(echo "$px * $spp / ($t1 - $t0) / 1000000" | bc -l | xargs printf %.2f) |"
  done
done

echo
echo "## Renderer alone: GL fp64 vs fp32 vs CPU reference"
echo
cmake --build "$root/$build" --target bench_plane_bench > /dev/null
cp "$root/$build/bench/bench_plane_bench" "$tmp/plane_bench"
"$tmp/plane_bench" "$glsize" "$spp" "$cpusize" "$root"/presets/2d/*.json
