#!/usr/bin/env bash
# Stills at equal quality: fraktal against mandelbulber2 (Debian 2.20, CPU), timed side by side in
# one run, each scored by the sampling error of its coverage (alpha) against its own converged
# coverage of the same scene, and compared at equal error.
# Usage: bench/stills/equal_quality.sh BUILD_DIR [WxH]   (default 640x360)
# Environment: SCENES (default "mandelbulb menger sierpinski_tetrahedron mandelbox"),
# PEER_AA (mandelbulber2 antialiasing sizes, default "1 2 3": 1, 4 and 9 samples per pixel),
# FRAKTAL_SPP (default "1 2 4 6 8 12 16"), TRUTH_SPP (a square, default 64).
#
# Why coverage: the two programs shade differently (their own lights, AO and colouring), so a
# colour metric measures that difference and not sampling error. Both write the share of each
# pixel the object covers (fraktal's A channel, mandelbulber2's 16-bit PNG alpha, averaged over its
# anti-aliasing samples), and the silhouette is where too few samples show as jaggies.
# Why each program's own truth: mandelbulber2's "Mandelbulb - Multi" at our settings draws a
# silhouette that is not quite ours (its coverage against our converged coverage: RMSE 0.18 at
# 320x180, at any detail level; our own 16 samples: 0.02), so each program is scored against its own converged coverage at the same size:
# fraktal at TRUTH_SPP fixed samples per pixel, mandelbulber2 at sqrt(TRUTH_SPP) x sqrt(TRUTH_SPP)
# anti-aliasing (a white-on-black mask: no lights, shadows or AO, the same geometry and samples).
# The comparison is of sampling error: how far each image is from what that program converges
# to, at what time. (A truth of 64 samples has about 1/8 of the 1-sample error itself, which the
# figures include.)
# The error is the RMSE of coverage over the whole image (bench/stills/coverage_error.cpp): only
# pixels on an edge can differ, and a per-edge-pixel figure would favour the wider filter (fraktal's
# Blackman-Harris of radius 2 spreads an edge over more pixels than mandelbulber2's box), while over
# the image it costs fraktal. The truth's edge pixel count is shown.
# Equal error: for each mandelbulber2 setting, the fastest fraktal setting whose error is at most
# mandelbulber2's, and the ratio of their times.
# Both render with their shadows and AO on (the scenes of bench/stills/run.sh); fraktal's time
# includes writing its 13-channel EXR. fraktal renders each spp adaptively (the default: a pixel
# stops once its samples agree) and with all samples ("fixed").
set -euo pipefail
build="${1:-build}"; size="${2:-640x360}"; truthSpp="${TRUTH_SPP:-64}"
truthAa=$(echo "sqrt($truthSpp)" | bc)
[[ $((truthAa * truthAa)) -eq $truthSpp ]] || { echo "TRUTH_SPP $truthSpp is not a square" >&2; exit 2; }
root="$(cd "$(dirname "$0")/../.." && pwd)"
read -r -a scenes <<< "${SCENES:-mandelbulb menger sierpinski_tetrahedron mandelbox}"
read -r -a peerAa <<< "${PEER_AA:-1 2 3}"
read -r -a fraktalSpp <<< "${FRAKTAL_SPP:-1 2 4 6 8 12 16}"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT

source "$root/bench/stills/peer.sh"

g++ -O2 -std=c++20 -I"$root" -I/usr/include/stb "$root/bench/stills/coverage_error.cpp" \
  $(pkg-config --cflags --libs OpenEXR) -lstb -o "$tmp/coverage_error"
now() { date +%s.%N; }
seconds() { echo "$2 - $1" | bc -l | xargs printf %.2f; }

summary=()
for name in "${scenes[@]}"; do
  "$root/$build/app/fraktal" render "$root/presets/$name.json" -o "$tmp/truth_$name.exr" --size "$size" \
    --spp "$truthSpp" --adaptive-tolerance 0 -q
  echo
  echo "$name, $size: coverage error against each program's truth ($truthSpp samples per pixel)"
  echo
  echo "| program | samples/px | s | coverage RMSE against its truth | edge pixels of the truth |"
  echo "|---|---|---|---|---|"
  declare -A fraktalTime=() fraktalError=()
  for spp in "${fraktalSpp[@]}"; do
    for mode in adaptive fixed; do
      [[ $spp -eq 1 && $mode == fixed ]] && continue  # one sample: nothing to adapt
      tolerance=$([[ $mode == fixed ]] && echo 0 || echo 0.01)
      t0=$(now)
      "$root/$build/app/fraktal" render "$root/presets/$name.json" -o "$tmp/f.exr" --size "$size" --spp "$spp" \
        --adaptive-tolerance "$tolerance" -q
      t=$(seconds "$t0" "$(now)")
      read -r error _ edges < <("$tmp/coverage_error" "$tmp/truth_$name.exr" "$tmp/f.exr")
      setting="$spp $mode"; [[ $spp -eq 1 ]] && setting=1
      fraktalTime[$setting]=$t; fraktalError[$setting]=$error
      echo "| fraktal | $setting | $t | $error | $edges |"
    done
  done
  if [[ $peer -eq 0 ]]; then
    echo "| mandelbulber2 | skipped | | | |"
    continue
  fi
  # mandelbulber2's truth: its anti-aliasing at sqrt(TRUTH_SPP) squared, drawing a mask (the object
  # white, the background black; no lights, shadows, AO or glow) to save time.
  sed "s/^antialiasing_enabled .*/antialiasing_enabled true;\nantialiasing_size $truthAa;/" "$root/bench/stills/$name.fract" |
    sed '/^shadows_enabled \|^ambient_occlusion_enabled \|^glow_enabled /d' |
    sed '/^\[main_parameters\]/a main_light_enable false;\nshadows_enabled false;\nambient_occlusion_enabled false;\nglow_enabled false;\nbackground_brightness 0;\nbackground_color_1 0000 0000 0000;\nbackground_color_2 0000 0000 0000;\nbackground_color_3 0000 0000 0000;\nmat1_is_defined true;\nmat1_luminosity 1;\nmat1_luminosity_color ffff ffff ffff;\nmat1_use_colors_from_palette false;\nmat1_surface_color 0000 0000 0000;\nmat1_specular 0;\nmat1_specular_plastic_enable false;\nmat1_metallic false;\nmat1_reflectance 0;' \
    > "$tmp/truth_$name.fract"
  HOME="$tmp" mandelbulber2 -n -f png16 -r "$size" -o "$tmp/mb_truth_$name" "$tmp/truth_$name.fract" > "$tmp/mb.log" 2>&1
  for aa in "${peerAa[@]}"; do
    # mandelbulber2 2.20 ignores -O for the anti-aliasing keys: set them in a copy of the settings.
    sed "s/^antialiasing_enabled .*/antialiasing_enabled $([[ $aa -gt 1 ]] && echo true || echo false);\nantialiasing_size $aa;/" \
      "$root/bench/stills/$name.fract" > "$tmp/$name.fract"
    t0=$(now)
    HOME="$tmp" mandelbulber2 -n -f png16alpha -r "$size" -o "$tmp/mb_$name" "$tmp/$name.fract" > "$tmp/mb.log" 2>&1
    t=$(seconds "$t0" "$(now)")
    read -r peerError _ edges < <("$tmp/coverage_error" "$tmp/mb_truth_$name.png" "$tmp/mb_$name.png")
    echo "| mandelbulber2 | $((aa * aa)) | $t | $peerError | $edges |"
    # The fastest fraktal setting at or under this error.
    best=""
    for setting in "${!fraktalTime[@]}"; do
      if (($(echo "${fraktalError[$setting]} <= $peerError" | bc -l))); then
        if [[ -z $best ]] || (($(echo "${fraktalTime[$setting]} < ${fraktalTime[$best]}" | bc -l))); then best=$setting; fi
      fi
    done
    if [[ -n $best ]]; then
      summary+=("| $name | $((aa * aa)) | $t | $peerError | $best | ${fraktalTime[$best]} | ${fraktalError[$best]} | $(echo "$t / ${fraktalTime[$best]}" | bc -l | xargs printf %.1f)x |")
    else
      summary+=("| $name | $((aa * aa)) | $t | $peerError | none of spp ${fraktalSpp[*]} | | | |")
    fi
  done
done

echo
echo "Equal error, $size: mandelbulber2's time against the fastest fraktal setting with at most its coverage error"
echo
echo "| scene | mandelbulber2 samples/px | mandelbulber2 s | its coverage RMSE | fraktal setting | fraktal s | fraktal coverage RMSE | mandelbulber2 / fraktal |"
echo "|---|---|---|---|---|---|---|---|"
for row in "${summary[@]}"; do echo "$row"; done
