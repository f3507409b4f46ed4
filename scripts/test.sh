#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run every test:
#   1. the test suite (ctest) on the Release build;
#   2. the unit tests again under AddressSanitizer + UBSan (build-asan/);
#   3. libFuzzer on the preset loader for FRAKTAL_FUZZ_SECONDS (default 60).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh

echo "== tests (Release)"
(cd build && ctest --output-on-failure --parallel "$(nproc)" --timeout 900)

echo "== tests under AddressSanitizer + UBSan"
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DFRAKTAL_SANITIZE=ON -DFRAKTAL_BUILD_EDITOR=OFF >/dev/null
cmake --build build-asan --parallel "$(nproc)" --target fraktal_tests fraktal
# Mesa (uninstrumented) keeps allocations until exit; leaks are checked in the tests without GL.
# The peak-memory test measures RSS, which ASan's shadow memory inflates: it runs in Release only.
ASAN_OPTIONS=detect_leaks=0 UBSAN_OPTIONS=print_stacktrace=1 build-asan/tests/fraktal_tests --gtest_brief=1 \
  --gtest_filter='-CliRender.LargeImagePeakMemoryIsBounded'
ASAN_OPTIONS=detect_leaks=1 build-asan/tests/fraktal_tests --gtest_brief=1 \
  --gtest_filter='Preset.*:PresetSave.*:DEQuality.*:GlslCompile.OnlyStructureChangesTheCode:CustomBlock.RoundTrips*:Editor*:ViewportLogic.*'

echo "== fuzzing the preset loader"
scripts/fuzz.sh "${FRAKTAL_FUZZ_SECONDS:-60}"
