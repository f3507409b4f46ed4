#!/usr/bin/env bash
# Stills benchmark: `fraktal render` against mandelbulber2 (Debian 2.20, CPU) on the same four
# scenes, same size, same samples per pixel, timed side by side in one run.
# Usage: bench/stills/run.sh BUILD_DIR [WxH] [SPP...]   (default 640x360, spp 1 and 4)
# The scenes: presets/<name>.json for fraktal, bench/stills/<name>.fract for mandelbulber2 (written by
# bench/stills/make_fract.py from the presets: same formula, parameters, iterations, bailout,
# camera, field of view, detail level; shadows and AO on; reflections and glow off).
# Anti-aliasing: fraktal --spp N (Blackman-Harris filtered jitter); mandelbulber2 antialiasing_size
# k = k x k samples, so spp 4 = size 2 (spp must be 1 or a square).
# Prints a Markdown table: seconds for each, the ratio mandelbulber2 / fraktal, fraktal's DE
# evaluations per pixel (bench/stills/de_count.cpp) and mandelbulber2's formula iterations per
# pixel (its --stats), for comparing the work done.
set -euo pipefail
build="${1:-build}"; size="${2:-640x360}"; spps=("${@:3}"); [[ ${#spps[@]} -gt 0 ]] || spps=(1 4)
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
g++ -O2 -std=c++20 -I"$root" "$root/bench/stills/de_count.cpp" "$root/$build/core/libfraktal_core.a" \
  $(pkg-config --cflags --libs OpenEXR OpenColorIO epoxy egl) -o "$tmp/de_count"
seconds() { echo "$2 - $1" | bc -l | xargs printf %.2f; }
echo "| fractal | size | spp | fraktal s | mandelbulber2 s | mandelbulber2 / fraktal | fraktal DE evals/px | mandelbulber2 iterations/px |"
echo "|---|---|---|---|---|---|---|---|"
for spp in "${spps[@]}"; do
  aa=$(echo "sqrt($spp)" | bc)
  [[ $((aa * aa)) -eq $spp ]] || { echo "spp $spp is not a square" >&2; exit 2; }
  for name in menger sierpinski_tetrahedron mandelbulb mandelbox; do
    # mandelbulber2 2.20 ignores -O for the anti-aliasing keys: set them in a copy of the settings.
    sed "s/^antialiasing_enabled .*/antialiasing_enabled $([[ $aa -gt 1 ]] && echo true || echo false);\nantialiasing_size $aa;/" \
      "$root/bench/stills/$name.fract" > "$tmp/$name.fract"
    t0=$(date +%s.%N)
    "$root/$build/app/fraktal" render "$root/presets/$name.json" -o "$tmp/$name.exr" --png "$tmp/$name.png" \
      --size "$size" --spp "$spp" -q
    t1=$(date +%s.%N)
    HOME="$tmp" mandelbulber2 -n --stats -f png -r "$size" -o "$tmp/mb_$name" "$tmp/$name.fract" > "$tmp/mb.log" 2>&1
    t2=$(date +%s.%N)
    de=$("$tmp/de_count" "$root/presets/$name.json" "$size" "$spp" | awk '{print $1}')
    iters=$(tr '\r' '\n' < "$tmp/mb.log" | grep "iters / pixel" | tail -1 | awk -F: '{print $NF}' | xargs printf %.0f)
    a=$(seconds "$t0" "$t1"); b=$(seconds "$t1" "$t2")
    echo "| $name | $size | $spp | $a | $b | $(echo "$b / $a" | bc -l | xargs printf %.2f)x | $de | $iters |"
    if [[ -n "${KEEP_IMAGES:-}" ]]; then  # a folder: keep both images of each scene to compare them
      cp "$tmp/$name.png" "$KEEP_IMAGES/fraktal_${name}_$spp.png"
      cp "$tmp/mb_$name.png" "$KEEP_IMAGES/mandelbulber2_${name}_$spp.png"
    fi
  done
done
