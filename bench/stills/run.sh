#!/usr/bin/env bash
# Stills benchmark: `fraktal render` against mandelbulber2 (Debian 2.20, CPU) on the classic
# fractals, same size, side by side in one run. Usage: bench/stills/run.sh BUILD_DIR [WxH] [SPP]
# Prints a Markdown table row per fractal: seconds for each and the ratio mandelbulber2 / fraktal.
# mandelbulber2 uses its toolbar scenes (its own camera, iterations and quality defaults, with
# AO and shadows); fraktal uses our presets at the same size. Comparable, not identical scenes.
set -euo pipefail
build="${1:-build}"; size="${2:-640x360}"; spp="${3:-4}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
tb=/usr/share/mandelbulber2/toolbar
declare -A peer=([mandelbulb]="$tb/mandelbulb_power_9.fract" [mandelbox]="$tb/mandelbox scale 2.fract"
                 [menger]="$tb/menger sponge.fract")
echo "| fractal | size | fraktal s ($spp spp) | mandelbulber2 s | mandelbulber2 / fraktal |"
echo "|---|---|---|---|---|"
for name in mandelbulb mandelbox menger; do
  t0=$(date +%s.%N)
  "$root/$build/app/fraktal" render "$root/presets/$name.json" -o "$tmp/$name.exr" --png "$tmp/$name.png" \
    --size "$size" --spp "$spp" -q
  t1=$(date +%s.%N)
  HOME="$tmp" mandelbulber2 -n -f png -r "$size" -o "$tmp/mb_$name" "${peer[$name]}" >/dev/null 2>&1
  t2=$(date +%s.%N)
  echo "| $name | $size | $(echo "$t1 - $t0" | bc -l | xargs printf %.2f) | $(echo "$t2 - $t1" | bc -l | xargs printf %.2f) | $(echo "($t2 - $t1) / ($t1 - $t0)" | bc -l | xargs printf %.2f)x |"
done
