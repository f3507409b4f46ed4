#!/usr/bin/env bash
# Overshoot as an image shows it: every shipped 3D preset rendered at its own step factor and at a
# quarter of it, with the hit threshold (--detail) also a quarter so that both stop where the
# factored estimate is the same (the hit test compares the factored estimate with the pixel
# footprint), and the depth (Z) of the two compared: pixels where the small-factor reference meets
# the object and the shipped factor does not, where the shipped factor lands more than 10 % behind
# the reference's hit (a step through a surface), and where it meets something the reference does
# not. Both march with up to 6000 steps, so a miss is a step past the surface, not a ray giving up;
# the reference with plain steps (over-relaxation and step growth 1: no relaxed or adaptive step).
# Frame 0 of animated presets, as the file holds it. FACTOR "shipped" takes each preset's own step
# factor; a number replaces it (1.0: what the estimates give before any measured factor).
# PRESETS (environment) names the preset files instead of presets/*.json.
# Usage: bench/stills/overshoot_pixels.sh BUILD_DIR [WxH] [FACTOR]   (default 640x360, shipped)
set -euo pipefail
build="${1:-build}"; size="${2:-640x360}"; override="${3:-shipped}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
fraktal="$root/$build/app/fraktal"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++20 "$root/bench/stills/depth_compare.cpp" $(pkg-config --cflags --libs OpenEXR) -o "$tmp/depth_compare"
echo "| preset | step factor | reference factor | reference hit pixels | missed | behind by > 10 % | extra hits |"
echo "|---|---|---|---|---|---|---|"
read -r -a presets <<< "${PRESETS:-$(echo "$root"/presets/*.json)}"
for preset in "${presets[@]}"; do
  name=$(basename "$preset" .json)
  factor=$(jq '.formula.deFactor // 1' "$preset")
  if [ "$override" != shipped ]; then
    factor="$override"
    jq --argjson f "$factor" '.formula.deFactor = $f' "$preset" > "$tmp/shipped.json"
    preset="$tmp/shipped.json"
  fi
  detail=$(jq '.render.detail // 0.5' "$preset")
  quarter=$(awk -v f="$factor" 'BEGIN { printf "%.6g", f / 4 }')
  jq --argjson f "$quarter" '.formula.deFactor = $f | .render.overRelaxation = 1 | .render.maxStepGrowth = 1' "$preset" \
    > "$tmp/reference.json"
  "$fraktal" render "$preset" -o "$tmp/shipped.exr" --size "$size" --spp 1 --float --max-steps 6000 -q
  "$fraktal" render "$tmp/reference.json" -o "$tmp/reference.exr" --size "$size" --spp 1 --float --max-steps 6000 \
    --detail "$(awk -v d="$detail" 'BEGIN { printf "%.6g", d / 4 }')" -q
  read -r hits missed deeper extra < <("$tmp/depth_compare" "$tmp/reference.exr" "$tmp/shipped.exr")
  echo "| $name | $factor | $quarter | $hits | $missed | $deeper | $extra |"
done
