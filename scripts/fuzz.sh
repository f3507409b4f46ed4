#!/usr/bin/env bash
# Fuzzes the preset loader and the Mandelbulber2 importer with libFuzzer (clang, AddressSanitizer +
# UBSan) for a bounded time, seeded with the shipped presets, the malformed-preset corpus and
# Mandelbulber2's toolbar settings files. The fuzzer is a target of the sanitizer build
# (tests/CMakeLists.txt, preset_fuzzer), built here when it is missing or stale.
# Usage: scripts/fuzz.sh [SECONDS]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
scripts/sanitize-build.sh preset_fuzzer
# The first folder collects new inputs; the seeds are only read.
corpus=build-asan/fuzz-corpus
mkdir -p "$corpus"
seeds=$(mktemp -d)
trap 'rm -rf "$seeds"' EXIT
find presets tests/bad_presets tests/legacy_presets -maxdepth 3 -type f -name '*.json' -size -64k -exec cp {} "$seeds"/ \;
# Fragmentarium frags, each after a comment line: text that starts with '/' goes to the .frag parser.
n=0
for frag in $(find tests/data/frag tests/data/frag_import -type f -name '*.frag' -size -64k); do
  { echo "// $frag"; cat "$frag"; } >"$seeds/frag$((n += 1)).frag"
done
if [ -d /usr/share/mandelbulber2/toolbar ]; then
  find /usr/share/mandelbulber2/toolbar -name '*.fract' -size -64k -exec cp {} "$seeds"/ \;
fi
build-asan/tests/preset_fuzzer -max_total_time="$seconds" -max_len=65536 -timeout=10 -rss_limit_mb=2048 \
  -print_final_stats=1 "$corpus" "$seeds" 2>&1 | tail -n 12
echo "fuzz: the preset loader, the importer and the frag parser survived ${seconds} s"
