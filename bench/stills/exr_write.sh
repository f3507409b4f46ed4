#!/usr/bin/env bash
# EXR writing alone: renders a cheap still with `fraktal render` (or takes IN.exr), then times
# ExrStripWriter writing it again from strips, with 1 compression thread and with one per core.
# Usage: bench/stills/exr_write.sh BUILD_DIR [WxH | IN.exr]
set -euo pipefail
build="${1:-build}"; what="${2:-8192x8192}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
# The harness links the core library that BUILD_DIR built (the writer and the strip layout).
cmake --build "$root/$build" --target bench_exr_write > /dev/null
cp "$root/$build/bench/bench_exr_write" "$tmp/exr_write"
if [[ "$what" == *.exr ]]; then in="$what"; else
  in="$tmp/in.exr"
  cat > "$tmp/cheap.json" <<'JSON'
{"format":"fraktal-preset","version":1,
 "formula":{"iterations":4,"bailout":1000,"boundRadius":1.8,"nodes":[{"block":"sierpinski_fold"},
   {"block":"scale","params":{"scale":2.0,"center":[1.0,1.0,1.0]}},{"block":"tetrahedron","params":{"size":1.0}}]},
 "camera":{"position":[2.2,1.4,3.1],"target":[0,-0.1,0]},
 "render":{"spp":1,"maxSteps":8},"shading":{"shadowSteps":0,"aoSteps":0}}
JSON
  /usr/bin/time -f "fraktal render $what (cheap scene, 1 spp): %e s wall, %M KiB peak RSS" \
    "$root/$build/app/fraktal" render "$tmp/cheap.json" -o "$in" --size "$what" -q
fi
"$tmp/exr_write" "$in" "$tmp/out.exr" 1
"$tmp/exr_write" "$in" "$tmp/out.exr" 0
