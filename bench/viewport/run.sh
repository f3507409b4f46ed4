#!/usr/bin/env bash
# Reproduces the viewport tables of bench/README.md, in one run so that the rows are
# measured side by side under the same load:
#   1. time: every shipped preset at 640x360 and 1280x720, orbit path at 1 degree per frame,
#      reprojection against restarting every ray (no reference renders, no rest phase);
#   2. error and work: every preset at 320x180 over 30 frames, each frame against the fully
#      converged (16-sample) render of its view and against the converged centre sample, then the
#      camera stops: frames until within 40 dB of the settled image;
#   3. as 2, but the path starts from the view at rest (settled at the AA cap, as a user's orbit
#      starts) instead of from an empty viewport;
#   4. switches and paths on the Mandelbulb and the Menger sponge: over-relaxation off, the cone
#      pre-pass on, the dolly and pan paths, the motion filter off, restarting with 45 and 60
#      steps per frame (restarting's error against its work, for comparisons at equal error);
#   5. a 60-frame orbit from rest on three presets: the work and error of frames 31-60, long after
#      the settled colours the orbit started with have been replaced (steady state).
# Usage: bench/viewport/run.sh BUILD_DIR [PRESET...]   (default: every preset in presets/)
set -euo pipefail
build=${1:?build dir}; shift
presets=("$@"); [ ${#presets[@]} -gt 0 ] || presets=(presets/*.json)
fraktal="$build/app/fraktal"

# Prints one table row from the JSON of `fraktal bench viewport`; frame 0 (the reset every mode
# starts with from an empty viewport) is left out of the "frames 1+" means.
row() {
  python3 -c '
import json, sys
d = json.load(sys.stdin)
label = sys.argv[1]
f = d["per_frame"][1:] or d["per_frame"]
ms = sum(x["ms"] for x in f) / len(f)
de = sum(x["de_evals_per_pixel"] for x in f) / len(f)
name = d["preset"].split("/")[-1].replace(".json", "")
def db(v): return "-" if v is None else "%.1f" % v
print("| %s | %dx%d | %s | %.0f | %.2f | %.2f | %s | %s | %s |" % (name, d["width"], d["height"], label, ms,
      d["mean_de_evals_per_pixel_per_frame"], de, db(d["mean_psnr_db"]), db(d["mean_psnr_centre_db"]),
      d["rest_frames_to_40db"] if d["rest_frames_to_40db"] >= 0 else "-"))' "$1"
}

echo "| preset | size | mode | ms/frame (frames 1+) | DE/px/frame (all) | DE/px/frame (frames 1+) | PSNR vs converged AA | PSNR vs centre sample | frames to 40 dB after stop |"
echo "|---|---|---|---|---|---|---|---|---|"
for p in "${presets[@]}"; do
  for size in 640x360 1280x720; do
    "$fraktal" bench viewport "$p" --size "$size" --frames 12 --degrees 1 --no-error --no-rest --json | row reproject
    "$fraktal" bench viewport "$p" --size "$size" --frames 12 --degrees 1 --no-error --no-rest --no-reproject --json | row restart
  done
done
for p in "${presets[@]}"; do
  "$fraktal" bench viewport "$p" --size 320x180 --frames 30 --degrees 1 --json | row reproject
  "$fraktal" bench viewport "$p" --size 320x180 --frames 30 --degrees 1 --no-reproject --json | row restart
done
for p in "${presets[@]}"; do
  "$fraktal" bench viewport "$p" --size 320x180 --frames 30 --degrees 1 --from-rest --json | row "reproject, from rest"
  "$fraktal" bench viewport "$p" --size 320x180 --frames 30 --degrees 1 --from-rest --no-reproject --json |
    row "restart, from rest"
done
for p in presets/mandelbulb.json presets/menger.json; do
  for variant in "--no-over-relaxation:reproject, no over-relaxation" "--no-over-relaxation --no-reproject:restart, no over-relaxation" \
                 "--cone-tile 8:reproject, cone pre-pass 8" "--cone-tile 8 --no-reproject:restart, cone pre-pass 8" \
                 "--path dolly:reproject, dolly" "--path dolly --no-reproject:restart, dolly" \
                 "--path pan:reproject, pan" "--path pan --no-reproject:restart, pan" \
                 "--no-motion-filter:reproject, no motion filter" \
                 "--no-reproject --steps 45:restart, 45 steps/frame" "--no-reproject --steps 60:restart, 60 steps/frame"; do
    flags=${variant%%:*}; label=${variant#*:}
    # shellcheck disable=SC2086
    "$fraktal" bench viewport "$p" --size 320x180 --frames 30 --degrees 1 --no-rest $flags --json | row "$label"
  done
done

# Section 5: frames 31-60 of a 60-frame orbit from rest.
steady() {
  python3 -c '
import json, sys
d = json.load(sys.stdin)
f = d["per_frame"][30:]
name = d["preset"].split("/")[-1].replace(".json", "")
print("| %s | %s | %.2f | %.1f dB | %.1f dB |" % (name, sys.argv[1], sum(x["de_evals_per_pixel"] for x in f) / len(f),
      sum(x["psnr_db"] for x in f) / len(f), min(x["psnr_db"] for x in f)))' "$1"
}
echo
echo "| preset | mode | DE evals/px/frame (frames 31-60) | mean PSNR vs converged AA (frames 31-60) | lowest |"
echo "|---|---|---|---|---|"
for p in presets/sierpinski_tetrahedron.json presets/menger.json presets/mandelbulb.json; do
  "$fraktal" bench viewport "$p" --size 320x180 --frames 60 --degrees 1 --from-rest --json | steady reproject
  "$fraktal" bench viewport "$p" --size 320x180 --frames 60 --degrees 1 --from-rest --no-reproject --json | steady restart
done
