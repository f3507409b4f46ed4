#!/usr/bin/env bash
# Configures and builds fraktal (Release) into build/: every target, or only the targets named
# (scripts/run.sh builds the program alone: `scripts/build.sh fraktal`).
set -euo pipefail
cd "$(dirname "$0")/.."
# ccache, when installed, makes rebuilds of unchanged sources free (it is optional).
launcher=(); command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
targets=(); for t in "$@"; do targets+=(--target "$t"); done
cmake --build build --parallel "$(nproc)" "${targets[@]}"
