// The editor's viewport on llvmpipe: the OCIO display pass gives the still export's PNG colours
// (fraktal::DisplayTransform) for every view of the shipped config, and the adapter around
// core/viewport settles, recompiles only on structure edits, and applies exposure and view at
// display only (the linear image is not rendered again). Small images: llvmpipe is slow.
#include <gtest/gtest.h>

#include <cmath>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/viewport/ocio_display_pass.hpp"
#include "app/editor/viewport/viewport_adapter.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

std::vector<uint8_t> readRgba8(GLuint texture, int w, int h) {
    std::vector<uint8_t> pixels(size_t(w) * h * 4);
    glGetTextureImage(texture, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    return pixels;
}

// An HDR test image in the working space: ramps from 0 to 16 in each channel and in grey, plus
// saturated colours, so tone mapping, gamut and the clip at 1 are all exercised.
std::vector<float> testImage(int w, int h) {
    std::vector<float> rgba(size_t(w) * h * 4);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float v = 16.0f * std::pow(float(x) / float(w - 1), 3.0f);
            float rgb[3] = {v, v, v};
            if (y < 3) rgb[(y + 1) % 3] = rgb[(y + 2) % 3] = 0.02f * v;  // red, green, blue ramps
            if (y == 4) rgb[2] = 0.0f;                                   // yellow
            float* p = &rgba[(size_t(y) * w + x) * 4];
            for (int c = 0; c < 3; ++c) p[c] = rgb[c];
            p[3] = 1.0f;
        }
    return rgba;
}

TEST(EditorDisplay, OcioGpuPassMatchesTheStillExportTransformForEveryView) {
    test::glContext();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    constexpr int w = 64, h = 6;
    const std::vector<float> image = testImage(w, h);
    GLuint linear = 0, target = 0, framebuffer = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &linear);
    glTextureStorage2D(linear, 1, GL_RGBA32F, w, h);
    glTextureSubImage2D(linear, 0, 0, 0, w, h, GL_RGBA, GL_FLOAT, image.data());
    glCreateTextures(GL_TEXTURE_2D, 1, &target);
    glTextureStorage2D(target, 1, GL_RGBA8, w, h);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, target, 0);

    OcioDisplayPass pass;
    for (const char* view : {"Standard", "ACES", "Raw"}) {
        for (double exposure : {-1.5, 0.0, 2.0}) {
            SCOPED_TRACE(std::string(view) + " exposure " + std::to_string(exposure));
            pass.configure(color, {"scene_linear", "sRGB", view});
            glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
            glViewport(0, 0, w, h);
            pass.draw(linear, exposure);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            const std::vector<uint8_t> gpu = readRgba8(target, w, h);

            std::vector<uint8_t> cpu(size_t(w) * h * 3);
            DisplayTransform(color, "scene_linear", "sRGB", view, exposure).toDisplay8(image, cpu);
            int worst = 0, distinct = 0;
            for (size_t i = 0; i < size_t(w) * h; ++i)
                for (int c = 0; c < 3; ++c) {
                    worst = std::max(worst, std::abs(int(gpu[i * 4 + c]) - int(cpu[i * 3 + c])));
                    distinct += i > 0 && cpu[i * 3 + c] != cpu[(i - 1) * 3 + c];
                }
            EXPECT_LE(worst, 1) << "8-bit levels between the viewport and the PNG export";
            EXPECT_GT(distinct, w) << "the test image spans many display levels";
        }
    }
    // The views differ, so matching each one is a real check (Standard clips, ACES tone-maps).
    std::vector<uint8_t> standard(size_t(w) * h * 3), aces(standard.size());
    DisplayTransform(color, "scene_linear", "sRGB", "Standard", 0.0).toDisplay8(image, standard);
    DisplayTransform(color, "scene_linear", "sRGB", "ACES", 0.0).toDisplay8(image, aces);
    EXPECT_NE(standard, aces);

    EXPECT_THROW(pass.configure(color, {"scene_linear", "sRGB", "NoSuchView"}), std::runtime_error);
    EXPECT_TRUE(pass.configured()) << "a bad view keeps the last good transform";
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &target);
    glDeleteTextures(1, &linear);
}

double spread(const std::vector<uint8_t>& rgba) {
    double sum = 0, sum2 = 0;
    const size_t n = rgba.size() / 4;
    for (size_t i = 0; i < n; ++i) {
        const double g = (rgba[i * 4] + rgba[i * 4 + 1] + rgba[i * 4 + 2]) / (3.0 * 255.0);
        sum += g;
        sum2 += g * g;
    }
    return std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
}

// Renders until the viewport settles; returns the number of frames it took. At rest a frame over
// the frame-time target marches fewer steps (a loaded machine), so the bound is generous.
int renderUntilSettled(ViewportView& v, const Preset& p, const ViewSettings& settings, int w, int h) {
    for (int frame = 1; frame <= 3000; ++frame) {
        v.render(p, settings, w, h);
        if (v.stats().settled) return frame;
    }
    return -1;
}

TEST(EditorViewport, SettlesRecompilesOnlyOnStructureEditsAndExposesAtDisplayOnly) {
    test::glContext();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    Preset p = loadPreset(test::sourceDir() / "presets" / "mandelbulb.json");
    ViewSettings settings;
    settings.aaCap = 2;
    settings.coneTile = 0;
    constexpr int w = 64, h = 40;
    CoreViewportView view(color);

    ASSERT_GT(renderUntilSettled(view, p, settings, w, h), 0);
    ASSERT_TRUE(view.compileError().empty()) << view.compileError();
    EXPECT_EQ(view.stats().compiles, 1);
    EXPECT_EQ(view.stats().aaLevel, 2);
    EXPECT_EQ(view.width(), w);
    EXPECT_EQ(view.height(), h);
    const std::vector<uint8_t> before = readRgba8(view.displayTexture(), w, h);
    EXPECT_GT(spread(before), 0.05) << "the fractal is visible, not a blank viewport";

    // Settled: another frame does no viewport work.
    view.render(p, settings, w, h);
    EXPECT_EQ(view.stats().deEvaluationsPerPixel, 0.0);
    EXPECT_EQ(view.stats().renderMs, 0.0);

    // Exposure and view change the display, not the scene-linear image: no frame is rendered.
    p.render.exposure = 1.5;
    p.render.view = "ACES";
    view.render(p, settings, w, h);
    EXPECT_TRUE(view.stats().settled);
    EXPECT_EQ(view.stats().deEvaluationsPerPixel, 0.0);
    EXPECT_TRUE(view.displayError().empty()) << view.displayError();
    const std::vector<uint8_t> exposed = readRgba8(view.displayTexture(), w, h);
    EXPECT_NE(exposed, before);

    // A parameter edit re-renders without compiling; a structure edit compiles once.
    p.formula.nodes[0].values[0].x = 6.0;
    ASSERT_GT(renderUntilSettled(view, p, settings, w, h), 0);
    EXPECT_EQ(view.stats().compiles, 1);
    p.formula.nodes[0].enabled = true;
    p.formula.iterations += 1;
    renderUntilSettled(view, p, settings, w, h);
    EXPECT_EQ(view.stats().compiles, 1) << "iterations are a uniform";
    p.formula.nodes.push_back(Node::make(*findBlock("box_fold")));
    ASSERT_GT(renderUntilSettled(view, p, settings, w, h), 0);
    EXPECT_EQ(view.stats().compiles, 2);

    // A bad OCIO view is reported and the last good display stays.
    p.render.view = "NoSuchView";
    view.render(p, settings, w, h);
    EXPECT_NE(view.displayError().find("NoSuchView"), std::string::npos);
    EXPECT_NE(view.displayTexture(), 0u);
}

// An object's colour in the viewport: the floor under the Menger sponge shows its colour, a change
// of it re-renders without compiling, and the colour is taken into the working space with the
// scene's others (in ACEScg the displayed floor is the one of linear Rec.709, as the still's is;
// left in Rec.709 numbers it would be shown another colour).
TEST(EditorViewport, ObjectColourIsAUniformInTheWorkingSpace) {
    test::glContext();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    Preset p = loadPreset(test::sourceDir() / "presets" / "menger.json");
    ASSERT_TRUE(addObject(p, *findObject("plane")));
    p.formula.objects[0].color = vec3(0.8, 0.3, 0.1);
    ViewSettings settings;
    settings.aaCap = 1;
    settings.coneTile = 0;
    constexpr int w = 64, h = 40;
    // The floor beside the sponge: the sides of the image's middle rows (either row order).
    auto floorMean = [&](const std::vector<uint8_t>& rgba) {
        glm::dvec3 sum(0.0);
        int n = 0;
        for (int y = h * 40 / 100; y < h * 60 / 100; ++y)
            for (int x = 0; x < w; ++x)
                if (x < w * 10 / 100 || x >= w * 90 / 100) {
                    const uint8_t* px = &rgba[(size_t(y) * w + size_t(x)) * 4];
                    sum += glm::dvec3(px[0], px[1], px[2]) / 255.0;
                    ++n;
                }
        return sum / double(n);
    };
    CoreViewportView view(color);
    ASSERT_GT(renderUntilSettled(view, p, settings, w, h), 0);
    ASSERT_TRUE(view.compileError().empty()) << view.compileError();
    const glm::dvec3 rust = floorMean(readRgba8(view.displayTexture(), w, h));
    EXPECT_GT(rust.x, 2.0 * rust.z) << rust.x << " " << rust.y << " " << rust.z;

    p.formula.objects[0].color = vec3(0.1, 0.3, 0.8);
    ASSERT_GT(renderUntilSettled(view, p, settings, w, h), 0);
    EXPECT_EQ(view.stats().compiles, 1) << "the colour is a uniform";
    const glm::dvec3 blue = floorMean(readRgba8(view.displayTexture(), w, h));
    EXPECT_GT(blue.z, 2.0 * blue.x) << blue.x << " " << blue.y << " " << blue.z;

    p.render.workingSpace = "ACEScg";
    ASSERT_GT(renderUntilSettled(view, p, settings, w, h), 0);
    const glm::dvec3 inAces = floorMean(readRgba8(view.displayTexture(), w, h));
    EXPECT_LT(glm::length(inAces - blue), 0.03) << inAces.x << " " << inAces.y << " " << inAces.z;
}

}  // namespace
}  // namespace fraktal::editor
