// A still written by the job reads back with OpenEXR: channels, types, chromaticities, the
// embedded preset; and the embedded preset renders the same image again.
#include <gtest/gtest.h>

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>

#include "core/image/exr_writer.hpp"
#include "core/render/still_job.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

namespace fs = std::filesystem;

fs::path tempDir(const std::string& name) {
    fs::path dir = fs::temp_directory_path() / ("fraktal_" + name + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

std::vector<float> readChannel(const fs::path& path, const char* name, int& width, int& height) {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    width = dw.max.x - dw.min.x + 1;
    height = dw.max.y - dw.min.y + 1;
    std::vector<float> data(size_t(width) * height);
    Imf::FrameBuffer fb;
    fb.insert(name, Imf::Slice(Imf::FLOAT, (char*)data.data(), sizeof(float), sizeof(float) * width));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return data;
}

StillJob smallJob(const fs::path& exr) {
    StillJob job;
    job.preset = loadPreset(test::sourceDir() / "presets" / "sierpinski_tetrahedron.json");
    job.preset.render.width = 64;
    job.preset.render.height = 40;
    job.preset.render.spp = 2;
    job.exr = exr;
    job.tileSize = 32;  // several strips and tiles
    return job;
}

TEST(ExrRoundTrip, ChannelsHeaderAndEmbeddedPreset) {
    test::glContext();
    const fs::path dir = tempDir("exr");
    StillJob job = smallJob(dir / "still.exr");
    job.png = dir / "still.png";
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    renderStillJob(job, color);
    ASSERT_TRUE(fs::exists(job.exr));
    ASSERT_TRUE(fs::exists(*job.png));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator{}), 2) << "temporary files left";

    Imf::InputFile in(job.exr.c_str());
    const Imf::Header& h = in.header();
    const std::map<std::string, Imf::PixelType> expected{
        {"R", Imf::HALF},       {"G", Imf::HALF},       {"B", Imf::HALF},       {"A", Imf::HALF},
        {"Z", Imf::FLOAT},      {"N.x", Imf::HALF},     {"N.y", Imf::HALF},     {"N.z", Imf::HALF},
        {"albedo.R", Imf::HALF}, {"albedo.G", Imf::HALF}, {"albedo.B", Imf::HALF}, {"AO", Imf::HALF},
        {"steps", Imf::FLOAT}};
    for (const auto& [name, type] : expected) {
        const Imf::Channel* c = h.channels().findChannel(name);
        ASSERT_NE(c, nullptr) << name;
        EXPECT_EQ(c->type, type) << name;
    }
    ASSERT_TRUE(Imf::hasChromaticities(h));
    const Imf::Chromaticities c = Imf::chromaticities(h);  // Rec.709 primaries, D65
    EXPECT_NEAR(c.red.x, 0.64, 2e-3);
    EXPECT_NEAR(c.red.y, 0.33, 2e-3);
    EXPECT_NEAR(c.green.x, 0.30, 2e-3);
    EXPECT_NEAR(c.blue.y, 0.06, 2e-3);
    EXPECT_NEAR(c.white.x, 0.3127, 2e-3);
    EXPECT_TRUE(Imf::hasWorldToCamera(h));

    const Preset embedded = parsePreset(readExrPreset(job.exr), "embedded");
    EXPECT_EQ(embedded.render, job.preset.render);
    EXPECT_EQ(embedded.formula.structureKey(), job.preset.formula.structureKey());
    EXPECT_EQ(embedded.camera.position, job.preset.camera.position);
    EXPECT_NE(describeExr(job.exr).find("fraktal.preset"), std::string::npos);

    // Depth and coverage agree: covered pixels have a finite depth inside the bound.
    int w, hgt;
    const std::vector<float> alpha = readChannel(job.exr, "A", w, hgt);
    const std::vector<float> depth = readChannel(job.exr, "Z", w, hgt);
    EXPECT_EQ(w, 64);
    EXPECT_EQ(hgt, 40);
    int covered = 0;
    for (size_t i = 0; i < alpha.size(); ++i)
        if (alpha[i] == 1.0f) {
            ++covered;
            EXPECT_LT(depth[i], 10.0f);
        }
    EXPECT_GT(covered, 50);

    // The embedded preset renders the same image.
    StillJob again = smallJob(dir / "again.exr");
    again.preset = embedded;
    renderStillJob(again, color);
    const std::vector<float> r1 = readChannel(job.exr, "R", w, hgt);
    const std::vector<float> r2 = readChannel(again.exr, "R", w, hgt);
    EXPECT_EQ(r1, r2);
    fs::remove_all(dir);
}

TEST(ExrRoundTrip, FullFloatAndAcescgChromaticities) {
    test::glContext();
    const fs::path dir = tempDir("exr_float");
    StillJob job = smallJob(dir / "still.exr");
    job.fullFloat = true;
    job.preset.render.workingSpace = "ACEScg";
    renderStillJob(job, ColorPipeline::fromFile(shippedOcioConfigPath()));
    Imf::InputFile in(job.exr.c_str());
    EXPECT_EQ(in.header().channels().findChannel("R")->type, Imf::FLOAT);
    const Imf::Chromaticities c = Imf::chromaticities(in.header());  // AP1 primaries, ACES white
    EXPECT_NEAR(c.red.x, 0.713, 2e-3);
    EXPECT_NEAR(c.green.y, 0.830, 2e-3);
    EXPECT_NEAR(c.white.x, 0.32168, 2e-3);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fraktal
