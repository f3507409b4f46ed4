#!/usr/bin/env bash
# Stills benchmark: `fraktal render` against mandelbulber2 (Debian 2.20, CPU) on the same four
# scenes, same size, same samples per pixel, timed side by side in one run, each render scored
# against a converged reference.
# Usage: bench/stills/run.sh BUILD_DIR [WxH] [SPP...]   (default 640x360, spp 1 and 4)
# Environment: REFERENCE_SPP (default 64), JSON (result file, default bench/stills/results.json),
# SCENES (default "menger sierpinski_tetrahedron mandelbulb mandelbox"), KEEP_IMAGES (a folder).
#
# The scenes: presets/<name>.json for fraktal, bench/stills/<name>.fract for mandelbulber2 (written by
# bench/stills/make_fract.py from the presets: same formula, parameters, iterations, bailout,
# camera, field of view, detail level; shadows and AO on; reflections and glow off).
# Anti-aliasing: fraktal --spp N (Blackman-Harris filtered jitter, adaptive: a pixel stops when its
# samples agree; "fixed" rows take all N); mandelbulber2 antialiasing_size k = k x k samples, so
# spp 4 = size 2 (spp must be 1 or a square).
# Quality: the reference is fraktal at REFERENCE_SPP fixed samples per pixel, same camera and
# formula; PSNR (dB, of the 8-bit sRGB PNGs, ImageMagick `compare -metric PSNR`) of each render
# against it. mandelbulber2 shades differently (its own light, AO and colouring), so its PSNR
# measures that difference as well as its sampling error.
# Work: fraktal's DE evaluations per pixel (bench/stills/de_count.cpp), mandelbulber2's formula
# iterations per pixel (its --stats).
# mandelbulber2 is installed (apt-get) when missing; when that fails its columns say "skipped".
set -euo pipefail
build="${1:-build}"; size="${2:-640x360}"; spps=("${@:3}"); [[ ${#spps[@]} -gt 0 ]] || spps=(1 4)
root="$(cd "$(dirname "$0")/../.." && pwd)"
referenceSpp="${REFERENCE_SPP:-64}"
json="${JSON:-$root/bench/stills/results.json}"
read -r -a scenes <<< "${SCENES:-menger sierpinski_tetrahedron mandelbulb mandelbox}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT

source "$root/bench/stills/peer.sh"

cmake --build "$root/$build" --target bench_de_count > /dev/null
cp "$root/$build/bench/bench_de_count" "$tmp/de_count"
seconds() { echo "$2 - $1" | bc -l | xargs printf %.2f; }
psnr() { compare -metric PSNR "$1" "$2" null: 2>&1 | awk '{printf "%.1f", $1}' || true; }
render() {  # PRESET OUT SPP TOLERANCE
  "$root/$build/app/fraktal" render "$root/presets/$1.json" -o "$tmp/$2.exr" --png "$tmp/$2.png" \
    --size "$size" --spp "$3" --adaptive-tolerance "$4" -q
}

echo "| fractal | size | spp | fraktal s | PSNR dB | DE evals/px | samples/px | fraktal fixed s | PSNR dB | DE evals/px | mandelbulber2 s | PSNR dB | iterations/px | mandelbulber2 / fraktal |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
rows=()
for name in "${scenes[@]}"; do
  render "$name" "ref_$name" "$referenceSpp" 0
  for spp in "${spps[@]}"; do
    aa=$(echo "sqrt($spp)" | bc)
    [[ $((aa * aa)) -eq $spp ]] || { echo "spp $spp is not a square" >&2; exit 2; }
    t0=$(date +%s.%N); render "$name" "$name" "$spp" 0.01
    t1=$(date +%s.%N); render "$name" "fixed_$name" "$spp" 0
    t2=$(date +%s.%N)
    mb="skipped"; mbPsnr="skipped"; iters="skipped"; ratio="skipped"
    if [[ $peer -eq 1 ]]; then
      # mandelbulber2 2.20 ignores -O for the anti-aliasing keys: set them in a copy of the settings.
      sed "s/^antialiasing_enabled .*/antialiasing_enabled $([[ $aa -gt 1 ]] && echo true || echo false);\nantialiasing_size $aa;/" \
        "$root/bench/stills/$name.fract" > "$tmp/$name.fract"
      HOME="$tmp" mandelbulber2 -n --stats -f png -r "$size" -o "$tmp/mb_$name" "$tmp/$name.fract" > "$tmp/mb.log" 2>&1
      t3=$(date +%s.%N)
      mb=$(seconds "$t2" "$t3"); mbPsnr=$(psnr "$tmp/mb_$name.png" "$tmp/ref_$name.png")
      iters=$(tr '\r' '\n' < "$tmp/mb.log" | grep "iters / pixel" | tail -1 | awk -F: '{print $NF}' | xargs printf %.0f)
    fi
    read -r de _ _ _ _ _ _ _ _ _ _ _ _ _ samples _ < <("$tmp/de_count" "$root/presets/$name.json" "$size" "$spp" 0.01)
    read -r deFixed _ < <("$tmp/de_count" "$root/presets/$name.json" "$size" "$spp" 0)
    a=$(seconds "$t0" "$t1"); b=$(seconds "$t1" "$t2")
    p=$(psnr "$tmp/$name.png" "$tmp/ref_$name.png"); pFixed=$(psnr "$tmp/fixed_$name.png" "$tmp/ref_$name.png")
    [[ $peer -eq 1 ]] && ratio="$(echo "$mb / $a" | bc -l | xargs printf %.2f)x"
    echo "| $name | $size | $spp | $a | $p | $de | $samples | $b | $pFixed | $deFixed | $mb | $mbPsnr | $iters | $ratio |"
    q() { [[ "$1" =~ ^[0-9.]+$ ]] && echo "$1" || echo "null"; }
    rows+=("{\"fractal\":\"$name\",\"size\":\"$size\",\"spp\":$spp,\"reference_spp\":$referenceSpp,\
\"fraktal_s\":$a,\"fraktal_psnr_db\":$(q "$p"),\"fraktal_de_evals_per_px\":$de,\"fraktal_samples_per_px\":$samples,\
\"fraktal_fixed_s\":$b,\"fraktal_fixed_psnr_db\":$(q "$pFixed"),\"fraktal_fixed_de_evals_per_px\":$deFixed,\
\"mandelbulber2_s\":$(q "$mb"),\"mandelbulber2_psnr_db\":$(q "$mbPsnr"),\"mandelbulber2_iterations_per_px\":$(q "$iters")}")
    if [[ -n "${KEEP_IMAGES:-}" ]]; then  # a folder: keep the images of each scene to compare them
      cp "$tmp/$name.png" "$KEEP_IMAGES/fraktal_${name}_$spp.png"
      cp "$tmp/ref_$name.png" "$KEEP_IMAGES/reference_${name}.png"
      [[ $peer -eq 1 ]] && cp "$tmp/mb_$name.png" "$KEEP_IMAGES/mandelbulber2_${name}_$spp.png"
    fi
  done
done
{
  echo "{\"benchmark\":\"stills\",\"date\":\"$(date -u +%FT%TZ)\",\"machine\":\"$(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)\",\"command\":\"bench/stills/run.sh $*\",\"mandelbulber2\":$([[ $peer -eq 1 ]] && echo true || echo false),\"rows\":["
  (IFS=,; echo "${rows[*]}")
  echo "]}"
} > "$json.tmp" && mv "$json.tmp" "$json"
echo "wrote $json" >&2
