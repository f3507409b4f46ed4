#!/usr/bin/env bash
# Quick start, command 1: install what is missing, build, and run the main job.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
preset="${1:-presets/mandelbulb.json}"
if ./build/app/fraktal --help | grep -q "  render"; then
  mkdir -p out
  ./build/app/fraktal render "$preset" -o out/default.exr --png out/default.png
  echo "run: rendered $preset to out/default.exr and out/default.png"
else
  ./build/app/fraktal check "$preset"
fi
