// The export dialog's render mode and its job's Done: the command carries `--mode path --spp N
// [--denoise]` as `fraktal render` takes them, the mode and path samples follow the view settings
// until chosen in the dialog, Done needs the files the job was asked for (and only those), an
// edit of the options after a job ends leaves its Done behind, and the preset handed to the
// renderer keeps its environment map reachable. And a file that is no preset is named as such.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "app/editor/document/export_job.hpp"
#include "app/editor/document/preset_files.hpp"
#include "app/editor/state/actions.hpp"
#include "editor_test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

struct ExportMode : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("fraktal_export_mode_" + std::to_string(::getpid()));
    void SetUp() override {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override { fs::remove_all(dir); }
};

TEST(EditorExportMode, PathCommandCarriesModeSamplesAndDenoise) {
    ExportOptions o;
    o.width = 96;
    o.height = 54;
    o.output = "out/kifs";
    o.pathTraced = true;
    o.pathSpp = 64;
    o.denoise = true;
    const std::vector<std::string> expected{"fraktal", "render",    "p.json", "-o",          "out/kifs.exr",
                                            "--size",  "96x54",     "--spp",  "64",          "--mode",
                                            "path",    "--denoise", "--png",  "out/kifs.png"};
    EXPECT_EQ(exportCommand("fraktal", "p.json", o), expected);
    o.pathTraced = false;
    const std::vector<std::string> fast{"fraktal", "render", "p.json", "-o",    "out/kifs.exr", "--size",
                                        "96x54",   "--spp",  "16",     "--png", "out/kifs.png"};
    EXPECT_EQ(exportCommand("fraktal", "p.json", o), fast) << "the fast mode: its own samples, no --denoise";
}

TEST(EditorExportMode, ModeFollowsTheViewUntilChosenAndAgainWhenTheViewChanges) {
    ExportOptions o;
    followViewMode(o, true, 256);
    EXPECT_TRUE(o.pathTraced);
    EXPECT_EQ(exportSpp(o), 256);
    o.pathTraced = false;  // chosen in the dialog
    followViewMode(o, true, 256);
    EXPECT_FALSE(o.pathTraced) << "a choice stands while the view's settings stay";
    followViewMode(o, false, 256);
    EXPECT_FALSE(o.pathTraced);
    followViewMode(o, true, 64);
    EXPECT_TRUE(o.pathTraced) << "the view changed: the export follows it";
    EXPECT_EQ(o.pathSpp, 64);
}

TEST(EditorExportMode, LightsTextNamesWhatTheModeRenders) {
    Lighting l;
    EXPECT_EQ(exportLightsText(l, false), "");
    for (int i = 0; i < 3; ++i) l.lights.push_back(Light{.type = LightType::Sphere});
    l.lights.push_back(Light{.type = LightType::Rect, .enabled = false});
    EXPECT_EQ(exportLightsText(l, true), "Lights: the preset's 3 sphere lights (the Lights tab).");
    EXPECT_EQ(exportLightsText(l, false).rfind("The fast renderer leaves out the preset's 3 sphere lights", 0), 0u);
    l.environment.map = "env/sky.exr";
    EXPECT_EQ(exportLightsText(l, true),
              "Lights: the preset's 3 sphere lights and the environment map (the Lights tab).");
}

TEST_F(ExportMode, DoneOnlyForTheFilesTheJobWroteWhileTheyExist) {
    ExportJob job;
    job.executable = FRAKTAL_CLI;
    job.options.output = (dir / "still").string();
    job.options.width = 32;
    job.options.height = 24;
    job.options.spp = 1;
    const Preset preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "menger.json");
    ASSERT_TRUE(startExport(job, preset, 0.0)) << job.log;
    job.options.output = (dir / "other").string();  // edited while it runs: the job keeps its files
    ASSERT_TRUE(test::pollUntilEnded(job, 120.0)) << job.log;
    ASSERT_EQ(job.status, ExportStatus::Done) << job.log;
    EXPECT_EQ(exportStatusText(job),
              "Done: " + (dir / "still.exr").string() + " and " + (dir / "still.png").string() + " (fast, 1 spp).");
    fs::remove(dir / "still.png");
    EXPECT_FALSE(exportOutputsExist(job));
    EXPECT_EQ(exportStatusText(job).find("Done"), std::string::npos) << exportStatusText(job);
    exportOptionsEdited(job);
    EXPECT_EQ(job.status, ExportStatus::Idle);

    // A renderer that exits 0 without writing the file: Failed, saying which file is missing.
    const fs::path fake = dir / "fake_renderer.sh";
    std::ofstream(fake) << "#!/bin/sh\necho progress 100%\nexit 0\n";
    fs::permissions(fake, fs::perms::owner_all);
    job.executable = fake;
    job.options.output = (dir / "never").string();
    ASSERT_TRUE(startExport(job, preset, 0.0)) << job.log;
    ASSERT_TRUE(test::pollUntilEnded(job, 30.0)) << job.log;
    EXPECT_EQ(job.status, ExportStatus::Failed);
    EXPECT_EQ(exportStatusText(job), "Failed: the renderer exited without writing " + (dir / "never.exr").string());
}

TEST(EditorExportMode, PresetTextMakesTheEnvironmentMapAbsolute) {
    Document d;
    d.preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "studio_mandelbulb.json");
    ASSERT_FALSE(d.preset.lighting.environment.map.empty());
    const fs::path file = fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "studio_mandelbulb.json";
    const Preset exported = parsePreset(exportPresetText(d, file), "export");
    EXPECT_TRUE(fs::path(exported.lighting.environment.map).is_absolute()) << exported.lighting.environment.map;
    EXPECT_TRUE(fs::is_regular_file(exported.lighting.environment.map)) << exported.lighting.environment.map;
    EXPECT_EQ(exportPresetText(d, {}), documentFileText(d)) << "an unsaved document: as it is";
}

TEST_F(ExportMode, ImagesAndBinaryFilesAreNamedNotParsed) {
    const unsigned char png[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13, 'I', 'H', 'D', 'R'};
    std::ofstream(dir / "x.png", std::ios::binary).write(reinterpret_cast<const char*>(png), sizeof png);
    std::ofstream(dir / "picture.json", std::ios::binary).write(reinterpret_cast<const char*>(png), sizeof png);
    std::ofstream(dir / "blob.json", std::ios::binary) << std::string("{\"a\": \xff\xfe}", 10);
    EXPECT_EQ(notAPresetReason(dir / "x.png").rfind("x.png is an image, not a fraktal preset (a PNG file): open", 0),
              0u)
        << notAPresetReason(dir / "x.png");
    EXPECT_EQ(notAPresetReason(dir / "picture.json").rfind("picture.json is an image", 0), 0u);
    EXPECT_EQ(notAPresetReason(dir / "blob.json").rfind("blob.json is a binary file, not a fraktal preset", 0), 0u);
    EXPECT_EQ(notAPresetReason(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "mandelbulb.json"), "");
    EditorState s;
    EXPECT_FALSE(openDocument(s, dir / "x.png"));
    EXPECT_EQ(s.status.text, notAPresetReason(dir / "x.png"));
}

}  // namespace
}  // namespace fraktal::editor
