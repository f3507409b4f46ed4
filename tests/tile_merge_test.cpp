// `fraktal render --part i/n` and `fraktal merge`: the merged parts equal a whole render bit for
// bit in every channel, with the same header attributes; missing or foreign parts are errors.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <cstring>
#include <map>

#include "core/image/exr_writer.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

// Every channel of an EXR as floats (half converts exactly), by name.
std::map<std::string, std::vector<float>> readChannels(const std::filesystem::path& path) {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    std::map<std::string, std::vector<float>> out;
    Imf::FrameBuffer fb;
    for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c) {
        auto& v = out[c.name()];
        v.resize(size_t(w) * size_t(h));
        fb.insert(c.name(), Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(v.data() - dw.min.x - size_t(dw.min.y) * w),
                                       sizeof(float), sizeof(float) * size_t(w)));
    }
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return out;
}

std::vector<std::string> attributeNames(const std::filesystem::path& path) {
    Imf::InputFile in(path.c_str());
    std::vector<std::string> names;
    for (auto a = in.header().begin(); a != in.header().end(); ++a) names.push_back(a.name());
    return names;
}

}  // namespace

TEST(TileMerge, MergedPartsEqualAWholeRenderBitForBit) {
    const auto dir = std::filesystem::temp_directory_path() / "fraktal_tile_merge_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string preset = (test::sourceDir() / "presets/mandelbulb.json").string();
    // Several samples per pixel: their positions must not depend on which part renders the pixel.
    const std::string common = "render " + preset + " -q --size 40x37 --spp 3 --tile 16 ";
    ASSERT_EQ(test::runCli(common + "-o " + (dir / "whole.exr").string()).exitCode, 0);
    for (int i = 1; i <= 3; ++i) {
        const test::CliRun r = test::runCli(common + "--part " + std::to_string(i) + "/3 -o " +
                                            (dir / ("p" + std::to_string(i) + ".exr")).string());
        ASSERT_EQ(r.exitCode, 0) << r.output;
    }
    const std::string parts =
        (dir / "p3.exr").string() + " " + (dir / "p1.exr").string() + " " + (dir / "p2.exr").string();
    const test::CliRun merge = test::runCli("merge " + parts + " -o " + (dir / "merged.exr").string());
    ASSERT_EQ(merge.exitCode, 0) << merge.output;

    const auto whole = readChannels(dir / "whole.exr"), merged = readChannels(dir / "merged.exr");
    ASSERT_EQ(whole.size(), 13u);
    ASSERT_EQ(merged.size(), whole.size());
    for (const auto& [name, values] : whole) {
        ASSERT_EQ(merged.at(name).size(), values.size()) << name;
        EXPECT_EQ(std::memcmp(merged.at(name).data(), values.data(), values.size() * sizeof(float)), 0) << name;
    }
    EXPECT_GT(*std::max_element(whole.at("A").begin(), whole.at("A").end()), 0.5f) << "the render is empty";
    EXPECT_EQ(readExrPreset(dir / "merged.exr"), readExrPreset(dir / "whole.exr"));
    EXPECT_EQ(attributeNames(dir / "merged.exr"), attributeNames(dir / "whole.exr"));
    // A part is not a whole image: it holds only its rows.
    EXPECT_LT(readChannels(dir / "p2.exr").at("R").size(), whole.at("R").size());

    // A missing part, a part given twice, a part of another image: clear errors, no file.
    const std::string out = " -o " + (dir / "bad.exr").string();
    const test::CliRun missing =
        test::runCli("merge " + (dir / "p1.exr").string() + " " + (dir / "p3.exr").string() + out);
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.output.find("are in no part"), std::string::npos) << missing.output;
    const test::CliRun twice = test::runCli("merge " + parts + " " + (dir / "p2.exr").string() + out);
    EXPECT_EQ(twice.exitCode, 2);
    EXPECT_NE(twice.output.find("overlap"), std::string::npos) << twice.output;
    const test::CliRun notPart = test::runCli("merge " + (dir / "whole.exr").string() + out);
    EXPECT_EQ(notPart.exitCode, 2);
    EXPECT_NE(notPart.output.find("not a part"), std::string::npos) << notPart.output;
    const test::CliRun badPart = test::runCli(common + "--part 4/3" + out);
    EXPECT_EQ(badPart.exitCode, 2);
    EXPECT_NE(badPart.output.find("part 4/3"), std::string::npos) << badPart.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "bad.exr"));
    std::filesystem::remove_all(dir);
}
