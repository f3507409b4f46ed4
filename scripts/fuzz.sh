#!/usr/bin/env bash
# Fuzzes the preset loader and the Mandelbulber2 importer with libFuzzer (clang, AddressSanitizer +
# UBSan) for a bounded time, seeded with the shipped presets, the malformed-preset corpus and
# Mandelbulber2's toolbar settings files. Usage: scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
out=build-fuzz
mkdir -p "$out"
sources=(core/preset.cpp core/json_reader.cpp core/preset_migrate.cpp core/formula.cpp core/custom_block.cpp core/camera.cpp
         core/atomic_file.cpp core/plane/plane_preset.cpp core/plane/plane_formula.cpp formulas/plane/registry.cpp
         core/lighting.cpp core/animation.cpp formulas/registry.cpp core/import/fract_file.cpp
         core/import/fract_import.cpp core/import/mb2_sequence.cpp core/scene_object.cpp tests/fuzz/preset_fuzzer.cpp)
if [ ! -x "$out/preset_fuzzer" ] || [ -n "$(find "${sources[@]}" core/*.hpp core/plane/*.hpp core/render/*.hpp core/anim/*.hpp core/import/* formulas/*.hpp formulas/plane/*.hpp -newer "$out/preset_fuzzer")" ]; then
  # One compiler per source, as many at once as there are cores (one clang++ over all the sources
  # used a single core: 2 of CI's 20 minutes), then the link. A failed compile stops the script
  # (set -e) when its job is waited for.
  flags=(-std=c++20 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined -I.)
  mkdir -p "$out/objects"
  objects=()
  for source in "${sources[@]}"; do
    objects+=("$out/objects/${source//\//_}.o")
    clang++ "${flags[@]}" -c "$source" -o "${objects[-1]}" &
    while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n; done
  done
  for job in $(jobs -p); do wait "$job"; done
  clang++ "${flags[@]}" "${objects[@]}" -o "$out/preset_fuzzer"
fi
# The first folder collects new inputs; the seeds are only read.
corpus="$out/corpus"
mkdir -p "$corpus"
seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT
find presets tests/bad_presets tests/legacy_presets -maxdepth 3 -type f -name '*.json' -size -64k -exec cp {} "$seeds"/ \;
if [ -d /usr/share/mandelbulber2/toolbar ]; then
  find /usr/share/mandelbulber2/toolbar -name '*.fract' -size -64k -exec cp {} "$seeds"/ \;
fi
"$out/preset_fuzzer" -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 "$corpus" "$seeds" 2>&1 | tail -n 12
echo "fuzz: the preset loader and the importer survived ${seconds} s"
