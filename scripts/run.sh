#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job: the editor when
# a display exists, otherwise a headless render of the default preset to EXR + PNG.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh fraktal  # the program alone: scripts/test.sh builds the tests
preset="${1:-presets/mandelbulb.json}"
if [ -n "${DISPLAY:-}" ]; then
  exec ./build/app/fraktal edit "$preset"
fi
mkdir -p out
echo "run: no display; rendering $preset headlessly (the editor needs a display)"
./build/app/fraktal render "$preset" -o out/default.exr --png out/default.png
echo "run: wrote $(pwd)/out/default.exr (scene-linear, with AOVs) and $(pwd)/out/default.png"
