// `fraktal render --tile i/n`: the same part of a still as --part i/n (one code path, the same
// file byte for byte); --tile N still sets the tile size; contradictions are clear errors.
#include <gtest/gtest.h>

#include <fstream>
#include <iterator>

#include "core/anim/sequence.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

std::string fileBytes(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(RenderTileOption, TileIOfNIsThePartOption) {
    const auto dir = std::filesystem::temp_directory_path() / "fraktal_render_tile_option_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string preset = (test::sourceDir() / "presets/mandelbulb.json").string();
    const std::string common = "render " + preset + " -q --size 40x37 --spp 2 ";

    const test::CliRun byTile = test::runCli(common + "--tile-size 16 --tile 2/3 -o " + (dir / "tile.exr").string());
    ASSERT_EQ(byTile.exitCode, 0) << byTile.output;
    const test::CliRun byPart = test::runCli(common + "--tile-size 16 --part 2/3 -o " + (dir / "part.exr").string());
    ASSERT_EQ(byPart.exitCode, 0) << byPart.output;
    const std::string tileBytes = fileBytes(dir / "tile.exr");
    EXPECT_GT(tileBytes.size(), 1000u);
    EXPECT_EQ(tileBytes, fileBytes(dir / "part.exr"));
    // It is part 2 of 3 of the still (rows, part attribute, embedded preset), not a whole image.
    Preset expected = loadPreset(preset);
    expected.render.width = 40;
    expected.render.height = 37;
    expected.render.spp = 2;
    std::string why;
    EXPECT_EQ(checkFrameFile(dir / "tile.exr", expected, &why, 1, 3), FrameFileState::Complete) << why;
    EXPECT_EQ(checkFrameFile(dir / "tile.exr", expected, &why, 0, 1), FrameFileState::Broken);
    EXPECT_NE(why.find("rows 12-23 of width 40, expected rows 0-36"), std::string::npos) << why;
    EXPECT_EQ(checkFrameFile(dir / "tile.exr", expected, &why, 0, 3), FrameFileState::Broken);

    // A bare number keeps meaning the tile size in pixels: the same whole image as --tile-size.
    ASSERT_EQ(test::runCli(common + "--tile 16 -o " + (dir / "a.exr").string()).exitCode, 0);
    ASSERT_EQ(test::runCli(common + "--tile-size 16 -o " + (dir / "b.exr").string()).exitCode, 0);
    EXPECT_EQ(fileBytes(dir / "a.exr"), fileBytes(dir / "b.exr"));
    EXPECT_NE(fileBytes(dir / "a.exr"), tileBytes);

    const test::CliRun both = test::runCli(common + "--tile 2/3 --part 1/3 -o " + (dir / "c.exr").string());
    EXPECT_EQ(both.exitCode, 2);
    EXPECT_NE(both.output.find("--tile 2/3 and --part 1/3"), std::string::npos) << both.output;
    const test::CliRun bad = test::runCli(common + "--tile 2of3 -o " + (dir / "c.exr").string());
    EXPECT_EQ(bad.exitCode, 2);
    EXPECT_NE(bad.output.find("--tile '2of3'"), std::string::npos) << bad.output;
    const test::CliRun outside = test::runCli(common + "--tile 4/3 -o " + (dir / "c.exr").string());
    EXPECT_EQ(outside.exitCode, 2);
    EXPECT_NE(outside.output.find("part 4/3"), std::string::npos) << outside.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "c.exr"));
    std::filesystem::remove_all(dir);
}
