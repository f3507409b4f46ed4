#!/usr/bin/env bash
# DE evaluations per pixel (and samples per pixel) of every shipped 3D preset's still at one size
# and sample count: machine-independent work, one row per preset.
# PRESETS (environment) names the preset files instead of presets/*.json.
# Usage: bench/stills/de_count_all.sh BUILD_DIR [WxH] [SPP]   (default 320x180, 1 spp)
set -euo pipefail
build="${1:-build}"; size="${2:-320x180}"; spp="${3:-1}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cmake --build "$root/$build" --target bench_de_count > /dev/null
cp "$root/$build/bench/bench_de_count" "$tmp/de_count"
echo "| preset | size | spp | DE evals/px | march steps per camera ray |"
echo "|---|---|---|---|---|"
read -r -a presets <<< "${PRESETS:-$(echo "$root"/presets/*.json)}"
for preset in "${presets[@]}"; do
  # "X DE evaluations per pixel (Y per sample), Z march steps per camera ray, W samples per pixel"
  read -r de steps < <("$tmp/de_count" "$preset" "$size" "$spp" | awk '{print $1, $9}')
  echo "| $(basename "$preset" .json) | $size | $spp | $de | $steps |"
done
