#!/usr/bin/env bash
# DE evaluations per pixel (and samples per pixel) of every shipped 3D preset's still at one size
# and sample count: machine-independent work, one row per preset.
# Usage: bench/stills/de_count_all.sh BUILD_DIR [WxH] [SPP]   (default 320x180, 1 spp)
set -euo pipefail
build="${1:-build}"; size="${2:-320x180}"; spp="${3:-1}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++20 -I"$root" "$root/bench/stills/de_count.cpp" "$root/$build/core/libfraktal_core.a" \
  $(pkg-config --cflags --libs OpenEXR OpenColorIO epoxy egl) -o "$tmp/de_count"
echo "| preset | size | spp | DE evals/px | march steps per camera ray |"
echo "|---|---|---|---|---|"
for preset in "$root"/presets/*.json; do
  # "X DE evaluations per pixel (Y per sample), Z march steps per camera ray, W samples per pixel"
  read -r de steps < <("$tmp/de_count" "$preset" "$size" "$spp" | awk '{print $1, $9}')
  echo "| $(basename "$preset" .json) | $size | $spp | $de | $steps |"
done
