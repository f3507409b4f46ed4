#!/usr/bin/env bash
# Quick start, command 2: install what is missing, build, and run every test:
#   1. the test suite (ctest) on the Release build;
#   2. the test files that make no GL context again under AddressSanitizer + UBSan (build-asan/),
#      and the command line's own paths under LeakSanitizer;
#   3. libFuzzer on the preset loader for FRAKTAL_FUZZ_SECONDS (default 30).
set -euo pipefail
cd "$(dirname "$0")/.."
# Each stage's wall time, printed as it ends and summed up at the end (CI's budget is 30 minutes).
stage_names=() stage_seconds=()
stage_start=$SECONDS
stage() {
  stage_names+=("$1")
  stage_seconds+=($((SECONDS - stage_start)))
  echo "-- stage '$1' took $((SECONDS - stage_start)) s"
  stage_start=$SECONDS
}
trap 'for i in "${!stage_names[@]}"; do printf "stage %-32s %5d s\n" "${stage_names[$i]}" "${stage_seconds[$i]}"; done' EXIT

# Every benchmark table names its command, date and commit (no build needed).
scripts/check_bench_tables.sh
scripts/install-deps.sh
stage "install"
scripts/build.sh
stage "Release build"

# The tests run at the niceness the editor gives its measuring threads (yieldToRendering, nice 10:
# the step factor's further rounds and the slow-stack advice give way to the viewport's rendering).
# At nice 0 those threads got a tenth of a core or less beside the other tests running in
# parallel, so every test and story that waits for a measurement waited for a starved thread:
# under the sanitizers, with four shards on two cores, SafeStep.EditorSetsTheCheckedFactorAfterA-
# StructureChange took 321 s and SafeStep.EditorMeasuresAnOpenedFileWhoseFactorWasNeverMeasured
# 279 s of their shards' time at nice 0, 62 s and 30 s at nice 10 (sum over all sanitizer tests:
# 1906 s -> 1140 s, with the same other load beside both runs).
run_tests() { nice -n 10 "$@"; }

echo "== tests (Release)"
(cd build && run_tests ctest --output-on-failure --parallel "$(nproc)" --timeout 900 -E '^SoakViewport')
stage "Release tests"

echo "== tests under AddressSanitizer + UBSan"
# Built with clang (scripts/sanitize-build.sh), with the preset fuzzer of stage 3. The test files
# that make a GL context are left out of this build (tests/CMakeLists.txt, FRAKTAL_TESTS_WITHOUT_GL):
# their work runs in Mesa's uninstrumented driver, and they run in the Release build above.
# The Release build's soak test runs beside this build: it measures its own resident memory over a
# fixed time (malloc's arenas and mmap threshold pinned, so that preemption by other processes
# does not grow it), not the time anything takes, and it needs one core (its 64x48 frames and its
# compiles are single-threaded), which it took alone for 145 s after the suite otherwise.
(cd build && ctest --output-on-failure --timeout 900 -R '^SoakViewport') >build/soak.log 2>&1 &
soak_pid=$!
scripts/sanitize-build.sh fraktal_tests fraktal preset_fuzzer
soak_failed=0
wait "$soak_pid" || soak_failed=1
echo "-- the soak test (Release), beside the sanitizer build"
cat build/soak.log
[ "$soak_failed" = 0 ] || { echo "the soak test failed" >&2; exit 1; }
stage "sanitizer build (the soak test beside it)"
# Leak detection is on in the test binary; the command lines it starts run without it
# (tests/child_sanitizer_options.cpp), and scripts/cli_leak_check.sh checks the command line's own
# paths for leaks instead, one process each. Mesa's driver, which keeps allocations until exit, is
# held loaded by core/gl/context.cpp so that they stay reachable instead of being reported from an
# "<unknown module>". The peak-memory test and the soak test measure RSS, which ASan inflates
# (shadow memory, and freed blocks held in its quarantine, 256 MB by default: the soak grew
# 80 MiB under ASan once, from 1.25 GiB, likely that): they run in Release only. The random-stack
# property test of the step factor (200 stacks, ~20 s of CPU) runs in Release only, and so does the
# comparison of imported Mandelbulber2 files with mandelbulber2's own renders (the import's code
# runs under the sanitizers in the other import tests). So do the tests that spend ten seconds or
# more of Release time measuring step factors or fitting estimators over thousands of rays (three to
# five times that under the sanitizers): their code runs under the sanitizers in the shorter tests
# of the same suites, on fewer rays. So does SafeStep.CheckSamplesMoreRaysWhereTheTailIsHeavy (5 s in
# Release, 165 s of its shard's time under the sanitizers: thousands of rays at -O1 without
# inlining); the tail rounds it measures run under the sanitizers in
# SafeStep.EditorSetsTheCheckedFactorAfterAStructureChange.
release_only='CliRender.LargeImagePeakMemoryIsBounded:SoakViewport.*:SafeStep.RandomStacksWithTheCheckedFactorNeverOvershoot:ImportVsMandelbulber2.*'
release_only+=':UndoDerived.EditorUndoesAndRedoesADeleteAcrossTheMeasurement:UndoDerived.UndoingAValueEditLetsTheMeasurementRunOn'
release_only+=':SafeStep.BulbPresetsShipWithAMeasuredFactorOfAtLeast08:SafeStep.EditorAppliesTheChecksFurtherRoundsWhenTheyEnd'
release_only+=':CheckFit.ApplyWritesTheSafeFactorOfAUselessEstimateAndFails:CheckFit.AUselessEstimateFailsAndNamesTheEstimatorTheFitChooses'
release_only+=':CheckFit.FitApplyWritesTheFittedFormulaAndKeepsTheRestOfTheFile:CheckFit.TheFitTakesNoEstimatorUnderWhichNoRayMeetsTheObject'
release_only+=':KleinianPresets.CameraInsideTheObjectFailsTheCheck:KleinianPresets.WrapOutsideItsGroupHasNoSafeStepFactor'
release_only+=':Preset.CheckCommandChecksAnAnimationFrame:SafeStep.CheckSamplesMoreRaysWhereTheTailIsHeavy'
# Shards side by side, two a core (the tests already run side by side under ctest; gtest deals the
# tests out by number, and with one shard a core the slow ones left one shard running 3 minutes
# after the other): each shard's output is printed whole once it ends, and any failing shard fails
# the run.
shards=$((2 * $(nproc)))
shard_pids=()
for ((shard = 0; shard < shards; shard++)); do
  GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$shard ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
    run_tests build-asan/tests/fraktal_tests --gtest_brief=1 --gtest_filter="-$release_only" >"build-asan/shard$shard.log" 2>&1 &
  shard_pids+=($!)
done
asan_failed=0
for ((shard = 0; shard < shards; shard++)); do
  wait "${shard_pids[$shard]}" || asan_failed=1
  echo "-- shard $((shard + 1)) of $shards"
  cat "build-asan/shard$shard.log"
done
[ "$asan_failed" = 0 ] || { echo "tests under AddressSanitizer + UBSan failed" >&2; exit 1; }
stage "sanitizer tests"
echo "== the command line under LeakSanitizer"
scripts/cli_leak_check.sh build-asan/app/fraktal
stage "LeakSanitizer on the CLI"

echo "== fuzzing the preset loader"
scripts/fuzz.sh "${FRAKTAL_FUZZ_SECONDS:-30}"
stage "fuzzing"
