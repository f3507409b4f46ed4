// The export dialog's job runs the real `fraktal render` with the flags it documents: the EXR
// (with the preset embedded) and the PNG appear, progress is read from its output, and a cancel
// stops it without leaving a file, while the caller never blocks.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <thread>

#include "app/editor/document/export_job.hpp"
#include "app/editor/state/actions.hpp"
#include "editor_test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

struct EditorExportJob : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("fraktal_export_" + std::to_string(::getpid()));
    Preset preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "mandelbulb.json");
    ExportJob job;
    void SetUp() override {
        fs::remove_all(dir);
        fs::create_directories(dir);
        job.executable = FRAKTAL_CLI;
        job.options.output = (dir / "still").string();
    }
    void TearDown() override {
        finishExport(job);
        fs::remove_all(dir);
    }
};

TEST_F(EditorExportJob, RendersTheExrWithTheEmbeddedPresetAndThePng) {
    job.options.width = 48;
    job.options.height = 32;
    job.options.spp = 1;
    preset.render.exposure = 0.5;  // travels in the preset, as the Render tab sets it
    ASSERT_TRUE(startExport(job, preset, 0.0)) << job.log;
    ASSERT_TRUE(test::pollUntilEnded(job, 120.0)) << job.log;
    ASSERT_EQ(job.status, ExportStatus::Done) << job.log;
    EXPECT_NEAR(job.progress, 1.0, 1e-9) << "the last progress line says 100%";
    EXPECT_TRUE(fs::exists(dir / "still.png"));
    const Preset embedded = presetFromExr(dir / "still.exr");
    EXPECT_EQ(embedded.formula.structureKey(), preset.formula.structureKey());
    EXPECT_EQ(embedded.render.exposure, 0.5);
    EXPECT_FALSE(fs::exists(job.presetFile)) << "the temporary preset is removed";
}

// A 2D document exports through the same job: the dialog hands `fraktal render` the 2D preset's
// text, and the still carries it under fraktal.planePreset (as the editor reopens it).
TEST_F(EditorExportJob, Exports2dDocumentsWithTheirPresetAndProgress) {
    Document d;
    d.plane = loadPlanePreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "2d" / "sierpinski_triangle.json");
    d.plane->view.width = 0.75;
    d.plane->render.exposure = -1.0;
    job.options.width = 40;
    job.options.height = 30;
    job.options.spp = 1;
    ASSERT_TRUE(startExport(job, documentFileText(d), 0.0)) << job.log;
    ASSERT_TRUE(test::pollUntilEnded(job, 120.0)) << job.log;
    ASSERT_EQ(job.status, ExportStatus::Done) << job.log;
    EXPECT_NEAR(job.progress, 1.0, 1e-9) << "2D progress lines carry a percentage too: " << job.log;
    EXPECT_TRUE(fs::exists(dir / "still.png"));
    const std::optional<PlanePreset> embedded = planePresetFromExr(dir / "still.exr");
    ASSERT_TRUE(embedded.has_value());
    EXPECT_EQ(embedded->view.width, 0.75);
    EXPECT_EQ(embedded->render.exposure, -1.0);
    EXPECT_EQ(embedded->render.width, 40) << "the size actually rendered";
    EXPECT_EQ(embedded->formula.structureKey(), d.plane->formula.structureKey());
}

TEST_F(EditorExportJob, CancelReturnsAtOnceAndLeavesNoFile) {
    job.options.width = 1600;
    job.options.height = 1200;
    job.options.spp = 64;
    ASSERT_TRUE(startExport(job, preset, 0.0)) << job.log;
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    test::expectCancelReturnsAtOnce(job, 120.0);
    if (HasFatalFailure()) return;
    EXPECT_FALSE(fs::exists(dir / "still.exr"));
    EXPECT_FALSE(fs::exists(dir / "still.png"));
}

TEST(EditorExport, CommandUsesTheRenderersFlagsAndProgressIsParsed) {
    ExportOptions o;
    o.width = 4961;
    o.height = 3508;
    o.spp = 9;
    o.output = "out/a3";
    o.halfFloat = false;
    const std::vector<std::string> cmd = exportCommand("fraktal", "p.json", o);
    const std::vector<std::string> expected{"fraktal",   "render", "p.json", "-o",    "out/a3.exr", "--size",
                                            "4961x3508", "--spp",  "9",      "--png", "out/a3.png", "--float"};
    EXPECT_EQ(cmd, expected);
    EXPECT_NEAR(parseProgress("progress: 1/10 tiles (10%)\nprogress: 3/10 tiles (30%), ETA 2s\n"), 0.3, 1e-12);
    EXPECT_EQ(parseProgress("rendering p.json: 48x32"), -1.0);
}

}  // namespace
}  // namespace fraktal::editor
