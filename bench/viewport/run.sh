#!/usr/bin/env bash
# Reproduces the "Viewport" table of bench/README.md: fraktal bench viewport on the orbit path,
# with and without reprojection, at 640x360 and 1280x720 (timing runs skip the per-frame
# reference renders), and one run with per-frame errors for PSNR and frames-to-40-dB.
# Usage: bench/viewport/run.sh BUILD_DIR [PRESET...]
set -euo pipefail
build=${1:?build dir}; shift
presets=("$@"); [ ${#presets[@]} -gt 0 ] || presets=(presets/mandelbulb.json)
for p in "${presets[@]}"; do
  for size in 640x360 1280x720; do
    for flag in "" --no-reproject; do
      "$build/app/fraktal" bench viewport "$p" --size "$size" --frames 10 --no-error $flag --json |
        python3 -c "import json,sys; d=json.load(sys.stdin); f=d['per_frame'][2:]; print('$p', '$size', 'reproject' if d['reproject'] else 'restart', 'ms/frame %.0f' % (sum(x['ms'] for x in f)/len(f)), 'DE/px/frame %.2f' % (sum(x['de_evals_per_pixel'] for x in f)/len(f)), 'rest frames to settle', d['rest_frames_to_settle'], 'settled DE/px', d['settled_de_evals_per_pixel'])"
    done
  done
  for flag in "" --no-reproject; do
    "$build/app/fraktal" bench viewport "$p" --size 320x180 --frames 10 $flag --json |
      python3 -c "import json,sys; d=json.load(sys.stdin); print('$p', '320x180', 'reproject' if d['reproject'] else 'restart', 'mean PSNR %.1f dB' % d['mean_psnr_db'], 'DE/px/frame %.2f' % d['mean_de_evals_per_pixel_per_frame'], 'rest frames to 40 dB', d['rest_frames_to_40db'])"
  done
done
