// Colour management: the shipped config's Standard view is the sRGB formula; a user config
// named by $OCIO is the one used; a broken config is a clear error.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "core/color/color_pipeline.hpp"

namespace fraktal {
namespace {

namespace fs = std::filesystem;

double srgbEncode(double linear) {  // IEC 61966-2-1
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

TEST(Ocio, StandardViewIsTheSrgbFormula) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const DisplayTransform display(color, "scene_linear", "sRGB", "Standard", 0.0);
    const double values[] = {0.0, 0.001, 0.01, 0.05, 0.18, 0.5, 0.8, 1.0};
    for (double v : values) {
        std::vector<float> rgb = {float(v), float(v), float(v), float(v), 0.0f, 0.0f};
        display.apply(rgb);
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(rgb[c], srgbEncode(v), 2e-3) << "grey " << v;
        EXPECT_NEAR(rgb[3], srgbEncode(v), 2e-3) << "red " << v;
        EXPECT_NEAR(rgb[4], 0.0, 2e-3);
    }
}

TEST(Ocio, ExposureIsInStops) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const DisplayTransform plusOne(color, "scene_linear", "sRGB", "Standard", 1.0);
    std::vector<float> rgb = {0.09f, 0.09f, 0.09f};
    plusOne.apply(rgb);
    EXPECT_NEAR(rgb[0], srgbEncode(0.18), 2e-3);
}

TEST(Ocio, AcesViewIsFilmicNotTheFormula) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const DisplayTransform aces(color, "scene_linear", "sRGB", "ACES", 0.0);
    std::vector<float> rgb = {4.0f, 4.0f, 4.0f, 0.18f, 0.18f, 0.18f};
    aces.apply(rgb);
    EXPECT_LT(rgb[0], 1.0f);  // highlights roll off instead of clipping
    EXPECT_GT(rgb[0], 0.8f);
    EXPECT_GT(rgb[3], 0.2f);
    EXPECT_LT(rgb[3], 0.6f);
}

TEST(Ocio, AcescgConversionKeepsGreyAndWidensPrimaries) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const vec3 grey = color.fromLinearRec709(vec3(0.5), "ACEScg");
    EXPECT_NEAR(grey.x, 0.5, 2e-3);
    EXPECT_NEAR(grey.z, 0.5, 2e-3);
    const vec3 red = color.fromLinearRec709(vec3(1, 0, 0), "ACEScg");  // Rec.709 red inside AP1
    EXPECT_NEAR(red.x, 0.613, 5e-3);
    EXPECT_GT(red.y, 0.05);
}

TEST(Ocio, UserConfigFromEnvironmentIsUsed) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_ocio_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    // The shipped config with an extra display that only this user config has.
    std::ifstream in(shippedOcioConfigPath());
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string anchor = "displays:\n";
    text.insert(text.find(anchor) + anchor.size(),
                "  Studio:\n    - !<View> {name: Graded, view_transform: Un-tone-mapped, display_colorspace: sRGB - Display}\n");
    text.replace(text.find("active_displays: [sRGB]"), 23, "active_displays: [sRGB, Studio]");
    text.replace(text.find("active_views: [Standard, ACES, Raw]"), 35, "active_views: [Standard, ACES, Raw, Graded]");
    const fs::path user = dir / "studio.ocio";
    std::ofstream(user) << text;
    ::setenv("OCIO", user.c_str(), 1);
    const ColorPipeline color = ColorPipeline::fromEnvironment();
    ::unsetenv("OCIO");
    EXPECT_EQ(color.configPath(), user);
    EXPECT_NO_THROW(color.checkDisplayView("Studio", "Graded"));
    EXPECT_THROW(ColorPipeline::fromFile(shippedOcioConfigPath()).checkDisplayView("Studio", "Graded"), std::runtime_error);
    fs::remove_all(dir);
}

TEST(Ocio, BrokenConfigNamesTheFile) {
    const fs::path bad = fs::temp_directory_path() / ("fraktal_broken_" + std::to_string(::getpid()) + ".ocio");
    std::ofstream(bad) << "ocio_profile_version: 2.1\nroles: [this is not a map\n";
    try {
        ColorPipeline::fromFile(bad);
        FAIL() << "a broken config was accepted";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find(bad.string()), std::string::npos) << e.what();
    }
    fs::remove(bad);
    EXPECT_THROW(ColorPipeline::fromFile("/nonexistent/config.ocio"), std::runtime_error);
}

TEST(Ocio, UnknownViewListsTheViews) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    try {
        color.checkDisplayView("sRGB", "Filmic");
        FAIL();
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("Standard"), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace fraktal
