# Read by ctest after the gtest list that gtest_discover_tests writes (tests/CMakeLists.txt): the
# gtests that took 20 s or more in CI's Release stage are started with the user stories, first, so
# that the suite does not end on one of them (CliRender.LargeImagePeakMemoryIsBounded, 69 s, was the
# last test to end on a fresh clone). A name that no longer exists is ignored by ctest: it only
# loses its place in the order. ctest orders by COST; a
# fresh clone has no timings of its own (CTestCostData.txt). The seconds are from a fresh clone's
# run with an empty shader cache (2026-11-29, b24a15a, `CI=true bash .ci/run`).
set(fraktal_long_gtests
    ImportVsMandelbulber2.FixedSetMatchesOrIsRefusedForItsReason 243
    SafeStep.RandomStacksWithTheCheckedFactorNeverOvershoot 172
    SceneChange.TheSettledViewportStartsAgainAndShowsTheChangedPresetForEveryKindOfField 123
    ViewportGL.ReprojectedImageConvergesToFreshRenderForEveryPreset 103
    CliRender.LargeImagePeakMemoryIsBounded 69
    SafeStep.BulbPresetsShipWithAMeasuredFactorOfAtLeast08 37
    ViewportGL.ReprojectionCutsDeEvaluationsAtEqualOrBetterError 27
    PortableLimits.EveryProgramFraktalLinksIsWithinOpenGL45 21
    GlslCompile.EveryBlockWithGlslang 21)
# Pairs: the test's name, its seconds.
list(LENGTH fraktal_long_gtests count)
math(EXPR last "${count} - 1")
foreach(i RANGE 0 ${last} 2)
  math(EXPR j "${i} + 1")
  list(GET fraktal_long_gtests ${i} name)
  list(GET fraktal_long_gtests ${j} seconds)
  set_tests_properties("${name}" PROPERTIES COST "${seconds}")
endforeach()
