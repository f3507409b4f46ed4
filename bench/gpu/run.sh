#!/usr/bin/env bash
# The GPU bench, on a lent GPU machine, in one command: `bash .gpu/run.sh` from a checkout that
# carries .gpu/ and .gl/ (made by bench/gpu/pack.sh). Fails fast when the renderer is not a GPU,
# then measures:
#   1. the viewport: orbit and dolly at 1280x720, 1920x1080 and 3840x2160 for mandelbulb,
#      mandelbox, menger and kleinian (p50 and p95 frame time, DE/px per frame, pass times, and
#      the time to settle after the camera stops);
#   2. stills: mandelbulb 1280x720 at 4 spp, 3840x2160, path traced at 256 spp, and a 16384^2
#      Menger at 1 spp with its peak memory (and 32768^2 with FRAKTAL_GPU_BIG=1);
#   3. the 240 frames of the power morph at 640x360;
#   4. `fraktal check` on every preset;
#   5. the editor under Xvfb with GLX on the NVIDIA driver: a screenshot and its frame times.
# Summary lines go to stdout; the JSON of every run and the screenshot go to $OUT (the lent
# machine's return folder) as gpu_bench.tar.gz and editor.png. Each step has its own time limit.
# FRAKTAL_GPU_DRY_RUN=1 runs every step small on whatever renderer there is (llvmpipe), with the
# build's own libraries, to check the script itself before spending a lent machine's time on it.
set -uo pipefail
cd "$(dirname "$0")/.."
out="${OUT:-/tmp/gpu_bench_out}"
work=$(mktemp -d)
mkdir -p "$out" "$work/json"
log() { printf '%s\n' "$*" | tee -a "$work/summary.txt"; }

dry="${FRAKTAL_GPU_DRY_RUN:-0}"
sizes=(1280x720 1920x1080 3840x2160) frames=120 big=16384 anim=0-239 spp=256 uhd=3840x2160
[ "$dry" = 1 ] && sizes=(320x180) frames=8 big=1024 anim=0-2 spp=4 uhd=640x360
if [ "$dry" != 1 ]; then
  # The GL dispatch libraries over the machine's NVIDIA driver (../shared/GPU.md).
  for f in .gl/*.deb; do dpkg -x "$f" / || { echo "FAIL: cannot unpack $f"; exit 1; }; done
  ldconfig
  vendor=/usr/local/nvidia/share/glvnd/egl_vendor.d/10_nvidia.json
  [ -f "$vendor" ] || vendor=$(ls /usr/share/glvnd/egl_vendor.d/*nvidia*.json 2>/dev/null | head -n 1)
  [ -n "$vendor" ] && export __EGL_VENDOR_LIBRARY_FILENAMES="$vendor"
fi
export OCIO="$PWD/.gpu/config/ocio/config.ocio"
# The carried libraries for the carried programs only (.gpu/with-libs), never for python3 or dpkg.
fraktal="$work/fraktal"
printf '#!/bin/sh\nexec "%s" "%s" "$@"\n' "$PWD/.gpu/with-libs" "$PWD/.gpu/fraktal" > "$fraktal"
chmod +x "$fraktal"
presets="$PWD/.gpu/presets"

# 0. The renderer must be the GPU, or nothing here means anything.
probe=$(timeout 120 "$fraktal" render "$presets/mandelbulb.json" -o "$work/probe.exr" --size 64x64 2>&1)
renderer=$(printf '%s\n' "$probe" | grep -o -m1 -iE '(NVIDIA|AMD|Radeon|Intel)[^,;)]*' || true)
[ "$dry" = 1 ] && renderer="${renderer:-$(printf '%s\n' "$probe" | grep -o -m1 'llvmpipe[^,;)]*') (dry run)}"
if [ -z "$renderer" ]; then
  echo "FAIL: the renderer is not a GPU:"; printf '%s\n' "$probe" | tail -n 5; exit 1
fi
driver=$(cat /proc/driver/nvidia/version 2>/dev/null | grep -o -m1 'Kernel Module  *[0-9.]*' | awk '{print $3}')
log "renderer: $renderer; driver: ${driver:-unknown}; $(date -u +%Y-%m-%d)"

# Percentiles, DE work, pass medians and settling from one `fraktal bench viewport --json`.
summarize() {
  python3 - "$1" <<'PY'
import json, statistics, sys
d = json.load(open(sys.argv[1]))
frames = d["per_frame"][1:] or d["per_frame"]
ms = sorted(f["ms"] for f in frames)
pct = lambda q: ms[min(len(ms) - 1, int(q * len(ms)))]
passes = {}
for f in frames:
    for name, t in (f.get("pass_ms") or {}).items():
        passes.setdefault(name, []).append(t)
p = " ".join("%s %.2f" % (k, statistics.median(v)) for k, v in passes.items())
print("p50 %.2f ms, p95 %.2f ms, DE/px/frame %.2f, settle %.0f ms; passes (median ms): %s" % (
    pct(0.5), pct(0.95), d["mean_de_evals_per_pixel_per_frame"], d.get("rest_ms_to_settle", -1), p))
PY
}

# 1. The viewport.
for preset in mandelbulb mandelbox menger kleinian; do
  for size in "${sizes[@]}"; do
    for path in orbit dolly; do
      json="$work/json/viewport_${preset}_${size}_${path}.json"
      if timeout 120 "$fraktal" bench viewport "$presets/$preset.json" --size "$size" --path "$path" --frames "$frames" \
          --no-error --time-passes --json > "$json" 2> "$json.err"; then
        log "viewport $preset $size $path: $(summarize "$json")"
      else
        log "viewport $preset $size $path: FAILED: $(tail -n 2 "$json.err" | tr '\n' ' ')"
      fi
    done
  done
done

# Wall time and peak memory of one command (GNU time may be missing on the lent machine).
timed() {
  python3 - "$@" <<'PY'
import resource, subprocess, sys, time
t = time.time()
r = subprocess.run(sys.argv[1:], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, timeout=500)
wall = time.time() - t
peak = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss / 1024
status = "ok" if r.returncode == 0 else "FAILED (%d): %s" % (r.returncode, r.stderr.decode()[-200:])
print("%.2f s wall, peak RSS %.0f MiB, %s" % (wall, peak, status))
PY
}

# 2. Stills.
log "still mandelbulb 1280x720 4 spp: $(timed "$fraktal" render "$presets/mandelbulb.json" -o "$work/s1.exr" --size 1280x720 --spp 4 -q)"
log "still mandelbulb $uhd: $(timed "$fraktal" render "$presets/mandelbulb.json" -o "$work/s2.exr" --size "$uhd" -q)"
log "path traced mandelbulb 1280x720 $spp spp: $(timed "$fraktal" render "$presets/mandelbulb.json" -o "$work/s3.exr" --size 1280x720 --mode path --spp "$spp" -q)"
log "still menger ${big}x$big 1 spp: $(timed "$fraktal" render "$presets/menger.json" -o "$work/big.exr" --size "${big}x$big" --spp 1 -q)"
rm -f "$work/big.exr"
if [ "${FRAKTAL_GPU_BIG:-0}" = 1 ]; then
  log "still menger 32768x32768 1 spp: $(timed "$fraktal" render "$presets/menger.json" -o "$work/big.exr" --size 32768x32768 --spp 1 -q)"
  rm -f "$work/big.exr"
fi

# 3. The animation.
mkdir -p "$work/anim"
log "animation power morph frames $anim 640x360: $(timed "$fraktal" render "$presets/mandelbulb_power_morph.json" --frames "$anim" -o "$work/anim/frame_####.exr" -q)"
rm -rf "$work/anim"

# 4. fraktal check on every preset.
passed=0; failed=()
checked=("$presets"/*.json)
[ "$dry" = 1 ] && checked=("$presets/menger.json")
for p in "${checked[@]}"; do
  if timeout 120 "$fraktal" check "$p" > "$work/json/check_$(basename "$p" .json).txt" 2>&1; then
    passed=$((passed + 1))
  else
    failed+=("$(basename "$p")")
  fi
done
log "fraktal check: $passed passed, ${#failed[@]} failed ${failed[*]:-}"

# 5. The editor under Xvfb, GLX on the NVIDIA driver.
if [ -x .gpu/bin/Xvfb ]; then
  export PATH="$PWD/.gpu/bin:$PATH"  # xkbcomp, which Xvfb runs
  xkb=(); [ -d .gpu/xkb ] && xkb=(-xkbdir "$PWD/.gpu/xkb")
  .gpu/with-libs Xvfb :77 -screen 0 1920x1080x24 "${xkb[@]}" > "$work/xvfb.log" 2>&1 &
  xvfb=$!
  sleep 2
  if DISPLAY=:77 __GLX_VENDOR_LIBRARY_NAME=nvidia timeout 120 "$fraktal" edit "$presets/mandelbulb.json" \
      --width 1920 --height 1080 --frames "$((frames * 2))" --screenshot "$out/editor.png" --frame-log "$work/json/editor_frames.jsonl" \
      > "$work/editor.log" 2>&1; then
    log "editor 1920x1080: $(python3 - "$work/json/editor_frames.jsonl" <<'PY'
import json, sys
f = [json.loads(l) for l in open(sys.argv[1]) if l.strip()]
ms = sorted(x.get("frame_ms", 0) for x in f[10:]) or [0]
print("%d frames, frame time p50 %.2f ms, p95 %.2f ms (screenshot editor.png)" % (
    len(f), ms[len(ms) // 2], ms[min(len(ms) - 1, int(0.95 * len(ms)))]))
PY
)"
  else
    log "editor 1920x1080: FAILED: $(tail -n 3 "$work/editor.log" | tr '\n' ' ')"
  fi
  kill "$xvfb" 2>/dev/null
fi

cp "$work/summary.txt" "$work/json/"
tar -C "$work" -czf "$out/gpu_bench.tar.gz" json
echo "gpu bench: done; $out/gpu_bench.tar.gz"
