#!/usr/bin/env bash
# LeakSanitizer over the command line's own paths: each command runs in a process of its own
# under the AddressSanitizer build, with leak detection on. The test binary starts its children
# without it (tests/child_sanitizer_options.cpp), because LeakSanitizer's thread tracer crashes
# now and then in a short-lived process ("Tracer caught signal 11", then "LeakSanitizer has
# encountered a fatal error": google/sanitizers#1353), which a test cannot tell from the
# command's own exit code. Here that crash is told apart from a leak by LeakSanitizer's own
# report and the command runs again, up to twice; a leak, or an exit code other than the one
# expected, fails.
# Usage: scripts/cli_leak_check.sh [FRAKTAL_BINARY]   (default build-asan/app/fraktal)
set -euo pipefail
cd "$(dirname "$0")/.."
fraktal="${1:-build-asan/app/fraktal}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# run EXPECTED_EXIT_CODE ARGS...
run() {
  local expected=$1 status attempt
  shift
  for attempt in 1 2 3; do
    status=0
    ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$fraktal" "$@" > "$work/output.txt" 2>&1 || status=$?
    if grep -q "LeakSanitizer: detected memory leaks" "$work/output.txt"; then
      cat "$work/output.txt"
      echo "FAILED: fraktal $*: leaks (above)"
      return 1
    fi
    if grep -q "Tracer caught signal" "$work/output.txt"; then
      echo "  fraktal $*: LeakSanitizer's tracer crashed (attempt $attempt), again"
      continue
    fi
    if [ "$status" -ne "$expected" ]; then
      cat "$work/output.txt"
      echo "FAILED: fraktal $*: exit code $status, expected $expected"
      return 1
    fi
    echo "  fraktal $*: no leaks (exit code $status)"
    return 0
  done
  echo "FAILED: fraktal $*: LeakSanitizer's tracer crashed three times"
  return 1
}

run 0 render presets/menger.json -o "$work/a.exr" --png "$work/a.png" --size 64x48 --spp 2 -q
run 0 render "$work/a.exr" -o "$work/b.exr" -q
run 0 info "$work/a.exr"
run 0 render presets/2d/julia.json -o "$work/julia.exr" --size 24x16 --spp 2 -q
run 0 render presets/mandelbulb_power_morph.json --frames 0-2 --size 32x18 --spp 1 -o "$work/f_####.exr" -q
rm -f "$work/f_0001.exr"
run 0 render presets/mandelbulb_power_morph.json --frames 0-2 --size 32x18 --spp 1 -o "$work/f_####.exr" -q
run 0 encode -q "$work/f_####.exr" -o "$work/video.mp4"
run 0 check presets/juliabulb.json --rays 16
run 2 render tests/bad_presets/unknown_block.json -o "$work/bad.exr" -q
run 2 render presets/menger.json -o "$work/no_such_folder/a.exr" -q
# The Mandelbulber2 importer: a file it maps, one it refuses (a formula id Mandelbulber2 does not
# have, 9999, which no mapping will ever take), one it cannot read.
printf '# Mandelbulber settings file\n# version 2.20\n[main_parameters]\nformula_1 7;\nN 6;\n' > "$work/sponge.fract"
printf '# Mandelbulber settings file\n# version 2.20\n[main_parameters]\nformula_1 9999;\n' > "$work/unmapped.fract"
printf 'Mandelbulber 1.21;\n' > "$work/old.fract"
run 0 import "$work/sponge.fract" -o "$work/sponge.json" -q
run 0 render "$work/sponge.fract" -o "$work/sponge.exr" --size 24x16 --spp 1 -q
run 2 import "$work/unmapped.fract" -o "$work/unmapped.json" -q
run 2 import "$work/old.fract" -o "$work/old.json" -q
# The Fragmentarium importer: a frag it maps (rendered straight from the frag too), one it refuses.
run 0 import tests/data/frag_import/menger.frag -o "$work/menger_frag.json" -q
run 0 render tests/data/frag_import/menger.frag -o "$work/menger_frag.exr" --size 24x16 --spp 1 -q
run 2 import tests/data/frag_import/unmappable.frag -o "$work/unmappable_frag.json" -q
