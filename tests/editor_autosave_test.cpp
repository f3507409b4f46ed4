// Session recovery: the autosave rule, the crash/clean-exit decision, and the file
// round trip through a simulated crash.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "app/editor/document/autosave.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

TEST(EditorAutosave, WritesOncePerMinuteOnlyUnsavedChangesNotYetWritten) {
    const double t0 = 100.0;
    EXPECT_EQ(autosaveDecision(t0 + 30, t0, true, "a", ""), AutosaveAction::Nothing) << "not a minute yet";
    EXPECT_EQ(autosaveDecision(t0 + 60, t0, true, "a", ""), AutosaveAction::Write);
    EXPECT_EQ(autosaveDecision(t0 + 600, t0, true, "a", "a"), AutosaveAction::Nothing) << "already in the file";
    EXPECT_EQ(autosaveDecision(t0 + 61, t0, true, "b", "a"), AutosaveAction::Write);
    EXPECT_EQ(autosaveDecision(t0 + 600, t0, false, "", "a"), AutosaveAction::Remove) << "saved: nothing to recover";
    EXPECT_EQ(autosaveDecision(t0 + 600, t0, false, "", ""), AutosaveAction::Nothing);
}

TEST(EditorAutosave, OffersRecoveryOnlyAfterAnUncleanEnd) {
    EXPECT_EQ(parseSessionMarker(""), PreviousSession::None);
    EXPECT_EQ(parseSessionMarker(R"({"state":"clean","pid":3})"), PreviousSession::Clean);
    EXPECT_EQ(parseSessionMarker(R"({"state":"running","pid":3})"), PreviousSession::Unclean);
    EXPECT_EQ(parseSessionMarker("{trunc"), PreviousSession::Unclean);
    EXPECT_TRUE(shouldOfferRecovery(PreviousSession::Unclean, true));
    EXPECT_TRUE(shouldOfferRecovery(PreviousSession::None, true));
    EXPECT_FALSE(shouldOfferRecovery(PreviousSession::Clean, true));
    EXPECT_FALSE(shouldOfferRecovery(PreviousSession::Unclean, false));
}

TEST(EditorAutosave, CrashThenRestartOffersTheAutosavedDocumentCleanExitDoesNot) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_autosave_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    Document doc;
    doc.preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "menger.json");
    doc.preset.formula.iterations = 3;
    doc.preset.shading.fogDensity = 0.7;
    doc.view.aaCap = 3;
    const fs::path original = "/somewhere/menger.json";

    AutosaveState first;
    ASSERT_TRUE(beginSession(first, dir, 0.0)) << first.error;
    EXPECT_FALSE(first.offer) << "a fresh folder has nothing to recover";
    AutosaveState concurrent;
    EXPECT_FALSE(beginSession(concurrent, dir, 0.0)) << "a second editor must not share the recovery file";
    autosaveTick(first, doc, original, /*dirty=*/true, 30.0);
    EXPECT_FALSE(fs::exists(first.paths.recovery)) << "not a minute yet";
    autosaveTick(first, doc, original, true, 61.0);
    finishAutosave(first);  // written on a thread of its own
    ASSERT_TRUE(fs::exists(first.paths.recovery)) << first.error;
    abandonSession(first);  // the crash: lock released, files left

    AutosaveState second;
    ASSERT_TRUE(beginSession(second, dir, 0.0)) << second.error;
    ASSERT_TRUE(second.offer);
    EXPECT_EQ(fingerprint(second.offer->doc), fingerprint(doc)) << "formula, settings and editor section";
    EXPECT_EQ(second.offer->originalFile, original);
    std::optional<RecoveryOffer> restored = answerRecovery(second, true);
    ASSERT_TRUE(restored);
    EXPECT_TRUE(fs::exists(second.paths.recovery)) << "kept until the restored document is saved";
    endSession(second);
    EXPECT_FALSE(fs::exists(second.paths.recovery));

    AutosaveState third;
    ASSERT_TRUE(beginSession(third, dir, 0.0));
    EXPECT_FALSE(third.offer) << "the previous session ended cleanly";
    // Declining a crash's offer deletes the recovery file.
    autosaveTick(third, doc, {}, true, 100.0);
    abandonSession(third);
    AutosaveState fourth;
    ASSERT_TRUE(beginSession(fourth, dir, 0.0));
    ASSERT_TRUE(fourth.offer);
    EXPECT_TRUE(fourth.offer->originalFile.empty());
    EXPECT_FALSE(answerRecovery(fourth, false));
    EXPECT_FALSE(fs::exists(fourth.paths.recovery));
    endSession(fourth);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fraktal::editor
