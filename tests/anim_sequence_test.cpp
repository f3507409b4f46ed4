// `fraktal render --frames`: frame ranges and paths, every frame written and complete, a rerun
// skipping complete frames and redoing a broken one, and bad input refused before any file.
#include <gtest/gtest.h>

#include <fstream>

#include "core/anim/sequence.hpp"
#include "core/image/exr_writer.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

const char* const kTinyAnimation = R"({
  "format": "fraktal-preset", "version": 3, "name": "tiny",
  "formula": {"iterations": 6, "boundRadius": 1.5, "deFactor": 0.5,
              "nodes": [{"block": "mandelbulb", "params": {"power": 8}}, {"block": "add_c"}, {"block": "escape_log"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "render": {"width": 24, "height": 16, "spp": 1},
  "animation": {"lastFrame": 5, "tracks": [
    {"target": "formula.nodes[0].params.power", "keys": [{"frame": 0, "value": 3}, {"frame": 5, "value": 8}]},
    {"target": "camera.position", "keys": [{"frame": 0, "value": [0, 0, 3]}, {"frame": 5, "value": [1, 0.5, 2.5]}]}
  ]}
})";

std::filesystem::path freshFolder(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string fileBytes(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

size_t count(const std::string& text, const std::string& what) {
    size_t n = 0;
    for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

}  // namespace

TEST(FrameSequence, RangesAndPaths) {
    EXPECT_EQ(parseFrameRange("0-5").frames(), (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_EQ(parseFrameRange("2-9:3").frames(), (std::vector<int>{2, 5, 8}));
    EXPECT_EQ(parseFrameRange("7").frames(), (std::vector<int>{7}));
    for (const char* bad : {"", "5-2", "a-b", "1-4:0", "-3", "1-2-3"})
        EXPECT_THROW(parseFrameRange(bad), std::runtime_error) << bad;
    EXPECT_EQ(framePath("out/f_####.exr", 12), "out/f_0012.exr");
    EXPECT_EQ(framePath("out/f_#.exr", 123), "out/f_123.exr");
    EXPECT_EQ(framePath("o#ut/f_##.exr", 3), "o#ut/f_03.exr");  // only the file name's run counts
    EXPECT_THROW(framePath("out/frame.exr", 1), std::runtime_error);
    EXPECT_THROW(framePath("out/f_##_##.exr", 1), std::runtime_error);
}

TEST(FrameSequence, RendersEveryFrameSkipsCompleteOnesAndRedoesBrokenOnes) {
    const auto dir = freshFolder("fraktal_sequence_test");
    const auto preset = dir / "tiny.json";
    std::ofstream(preset) << kTinyAnimation;
    const std::string args = "render " + preset.string() + " --frames 0-5:2 -o " + (dir / "f_###.exr").string();
    const test::CliRun first = test::runCli(args);
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(first.output.find("frame 3/3 (4)"), std::string::npos) << first.output;
    EXPECT_NE(first.output.find("remaining"), std::string::npos) << first.output;
    const Preset animated = loadPreset(preset);
    for (int f : {0, 2, 4}) {
        const auto path = dir / ("f_00" + std::to_string(f) + ".exr");
        EXPECT_EQ(checkFrameFile(path, sequenceFramePreset(animated, f)), FrameFileState::Complete) << path;
        // The frame's own values are embedded: it re-renders as that frame.
        const Preset embedded = parsePreset(readExrPreset(path), path.string());
        EXPECT_DOUBLE_EQ(embedded.formula.nodes[0].values[0].x, 3.0 + f);
        EXPECT_TRUE(embedded.animation.empty());
    }
    EXPECT_FALSE(std::filesystem::exists(dir / "f_001.exr"));
    // Another frame's file is not taken for this one.
    EXPECT_EQ(checkFrameFile(dir / "f_002.exr", sequenceFramePreset(animated, 3)), FrameFileState::Broken);

    const std::string frame2 = fileBytes(dir / "f_002.exr");
    const test::CliRun again = test::runCli(args);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(count(again.output, "complete, skipped"), 3u) << again.output;

    // Cut frame 2 short: the rerun renders it (alone) again, to the same pixels.
    std::filesystem::resize_file(dir / "f_002.exr", frame2.size() / 2);
    EXPECT_EQ(checkFrameFile(dir / "f_002.exr", sequenceFramePreset(animated, 2)), FrameFileState::Broken);
    const test::CliRun repair = test::runCli(args);
    ASSERT_EQ(repair.exitCode, 0) << repair.output;
    EXPECT_EQ(count(repair.output, "complete, skipped"), 2u) << repair.output;
    EXPECT_NE(repair.output.find("f_002.exr is incomplete"), std::string::npos) << repair.output;
    EXPECT_EQ(fileBytes(dir / "f_002.exr"), frame2);
    std::filesystem::remove_all(dir);
}

// An on/off parameter keyed off at frame 0 and on at frame 4 (smooth, the default): every rendered
// frame embeds it off until frame 4 and on from there, never a value in between.
TEST(FrameSequence, AKeyedToggleIsOffOrOnInEveryFrame) {
    const auto dir = freshFolder("fraktal_sequence_toggle_test");
    const auto preset = dir / "toggle.json";
    std::string text = kTinyAnimation;
    const std::string power = R"({"target": "formula.nodes[0].params.power")";
    text.insert(text.find(power), R"({"target": "formula.nodes[1].params.julia",
     "keys": [{"frame": 0, "value": 0}, {"frame": 4, "value": 1}]},
    )");
    std::ofstream(preset) << text;
    const test::CliRun run =
        test::runCli("render " + preset.string() + " -q --frames 0-5 -o " + (dir / "f_#.exr").string());
    ASSERT_EQ(run.exitCode, 0) << run.output;
    for (int f = 0; f <= 5; ++f) {
        const auto path = dir / ("f_" + std::to_string(f) + ".exr");
        const Preset embedded = parsePreset(readExrPreset(path), path.string());
        const Node& addC = embedded.formula.nodes[1];
        EXPECT_EQ(addC.values[size_t(addC.block->paramIndex("julia"))].x, f < 4 ? 0.0 : 1.0) << path;
    }
    std::filesystem::remove_all(dir);
}

// --mode path renders every frame path-traced: each file has the path tracer's passes and is
// complete for a rerun, which skips it.
TEST(FrameSequence, PathTracedFramesCarryThePassesAndAreSkippedWhenComplete) {
    const auto dir = freshFolder("fraktal_sequence_path_test");
    const auto preset = dir / "tiny.json";
    std::ofstream(preset) << kTinyAnimation;
    const std::string args =
        "render " + preset.string() + " --mode path --frames 0-5:5 -o " + (dir / "p_#.exr").string();
    const test::CliRun run = test::runCli(args);
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const Preset animated = loadPreset(preset);
    for (int f : {0, 5}) {
        const auto path = dir / ("p_" + std::to_string(f) + ".exr");
        EXPECT_EQ(checkFrameFile(path, sequenceFramePreset(animated, f)), FrameFileState::Complete) << path;
        EXPECT_NE(fileBytes(path).find("diffuse_direct.R"), std::string::npos) << path;
    }
    const test::CliRun again = test::runCli(args);
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_EQ(count(again.output, "complete, skipped"), 2u) << again.output;
    // Parts are for fast stills only.
    const test::CliRun part = test::runCli("render " + preset.string() + " --mode path --tile 1/2 -o " +
                                           (dir / "part.exr").string());
    EXPECT_NE(part.exitCode, 0);
    EXPECT_NE(part.output.find("--tile/--part"), std::string::npos) << part.output;
    std::filesystem::remove_all(dir);
}

TEST(FrameSequence, BadRangesAndFoldersAreClearErrors) {
    const auto dir = freshFolder("fraktal_sequence_bad_test");
    const auto preset = dir / "tiny.json";
    std::ofstream(preset) << kTinyAnimation;
    struct Case {
        std::string args;
        std::string message;
    };
    const Case cases[] = {
        {"--frames 0-9 -o " + (dir / "f_##.exr").string(), "outside the animation"},
        {"--frames 3-1 -o " + (dir / "f_##.exr").string(), "the last frame is before the first"},
        {"--frames 0-2 -o " + (dir / "missing/f_##.exr").string(), "does not exist"},
        {"--frames 0-2 -o " + (dir / "f.exr").string(), "needs '#'"},
    };
    for (const Case& c : cases) {
        const test::CliRun r = test::runCli("render " + preset.string() + " " + c.args);
        EXPECT_EQ(r.exitCode, 2) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
    }
    const test::CliRun still = test::runCli("render " + (test::sourceDir() / "presets/menger.json").string() +
                                            " --frames 0-2 -o " + (dir / "f_##.exr").string());
    EXPECT_EQ(still.exitCode, 2);
    EXPECT_NE(still.output.find("has no animation section"), std::string::npos) << still.output;
    int files = 0;
    for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 1) << "only the preset: no frame, no temporary file";
    std::filesystem::remove_all(dir);
}
