#!/usr/bin/env bash
# What a still's memory and time do as the image gets wider: renders the same 256-row band of
# presets/menger.json (1 spp, from the middle of the image: the band that crosses the object) at
# 16384 and 32768 pixels wide with `fraktal render --part`, reporting wall time, peak RSS and the
# EXR's size; then times ExrStripWriter alone rewriting each band with 2 and 16 compression
# threads (bench/stills/exr_write.cpp), as a 16-core machine would write it. A band of the whole
# image's width holds everything that grows with the width (strips, OpenEXR's blocks in flight);
# the rows only add time.
# Usage: bench/stills/wide_exr.sh BUILD_DIR
set -euo pipefail
build="${1:-build}"
root="$(cd "$(dirname "$0")/../.." && pwd)"
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
cmake --build "$root/$build" --target bench_exr_write > /dev/null
cp "$root/$build/bench/bench_exr_write" "$tmp/exr_write"
for spec in "16384 32 64" "32768 64 128"; do
  set -- $spec
  /usr/bin/time -f "render ${1} wide, 256 rows (part $2/$3): %e s wall, %U s user, peak RSS %M KiB" \
    "$root/$build/app/fraktal" render "$root/presets/menger.json" -o "$tmp/band$1.exr" --size "$1x$1" --spp 1 \
    --part "$2/$3" -q
  echo "  EXR $(stat -c %s "$tmp/band$1.exr") bytes"
  for threads in 2 16; do
    /usr/bin/time -f "  peak RSS %M KiB" "$tmp/exr_write" "$tmp/band$1.exr" "$tmp/out.exr" "$threads"
  done
done 2>&1
