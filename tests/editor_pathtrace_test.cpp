// The editor viewport's "Path traced at rest" mode on llvmpipe: at rest it accumulates the same
// samples as `fraktal render --mode path` (renderPathJob, the export) for the same preset, camera
// and size, shows them through the same display transform as the export's PNG, and any change of
// the view drops the accumulation back to the fast mode. Small images: llvmpipe is slow.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/editor/viewport/viewport_adapter.hpp"
#include "core/render/path_job.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

constexpr int kW = 96, kH = 64, kSpp = 8;

// The Mandelbulb with the shipped sky environment and a sphere light, so that the path tracer's
// own inputs (lights, environment map relative to the preset file) are all part of the scene.
Preset litMandelbulb() {
    Preset p = loadPreset(test::sourceDir() / "presets" / "mandelbulb.json");
    p.lighting.environment.map = "env/sky.exr";
    Light sphere;
    sphere.type = LightType::Sphere;
    sphere.position = vec3(1.5, 2.0, 2.0);
    sphere.size = 0.3;
    sphere.intensity = 8.0;
    p.lighting.lights.push_back(sphere);
    return p;
}

std::string presetFile() { return (test::sourceDir() / "presets" / "mandelbulb.json").string(); }

ViewSettings pathSettings() {
    ViewSettings v;
    v.pathTraceAtRest = true;
    v.pathSppCap = kSpp;
    v.aaCap = 2;
    v.frameTimeTargetMs = 0.0;  // full size always, one whole sample pass per frame
    return v;
}

// Frames until the viewport shows `spp` path-traced samples; -1 if it never does.
// `midPassFrames`, when given, counts the frames that ended inside a sample pass (in bands).
int renderUntilPathSpp(CoreViewportView& view, const Preset& p, const ViewSettings& v, int spp,
                       int* midPassFrames = nullptr) {
    for (int frame = 1; frame <= 5000; ++frame) {
        view.render(p, v, kW, kH);
        if (!view.compileError().empty() || !view.displayError().empty()) return -1;
        if (midPassFrames && view.pathTracer() && view.pathTracer()->rowsDone() > 0) ++*midPassFrames;
        if (view.stats().pathTracing && view.stats().pathSamples >= spp) return frame;
    }
    return -1;
}

PathImage readExrBeauty(const std::filesystem::path& file) {
    Imf::InputFile in(file.c_str());
    const Imath::Box2i box = in.header().dataWindow();
    PathImage image;
    image.resize(box.max.x - box.min.x + 1, box.max.y - box.min.y + 1);
    Imf::FrameBuffer fb;
    const size_t xStride = 4 * sizeof(float), yStride = xStride * size_t(image.width);
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c)
        fb.insert(names[c], Imf::Slice(Imf::FLOAT, (char*)(image.passes[kBeauty].data() + c), xStride, yStride));
    in.setFrameBuffer(fb);
    in.readPixels(box.min.y, box.max.y);
    return image;
}

// `frameTimeTargetMs`: 0 renders a whole sample pass per frame; a small target spreads each pass
// over many frames in bands of rows (PathTracer::addSampleRows).
void expectViewportEqualsExport(double frameTimeTargetMs) {
    test::glContext();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    const Preset p = litMandelbulb();
    CoreViewportView view(color);
    view.setPresetFile(presetFile());
    ViewSettings v = pathSettings();
    v.frameTimeTargetMs = frameTimeTargetMs;

    // The first frames are the fast mode's; once its view rests the path tracer takes over.
    view.render(p, v, kW, kH);
    EXPECT_FALSE(view.stats().pathTracing);
    int midPass = 0;
    const int frames = renderUntilPathSpp(view, p, v, kSpp, &midPass);
    ASSERT_GT(frames, 0) << view.compileError() << view.displayError();
    std::printf("frame-time target %.1f ms: %d spp in %d frames, %d of them ending inside a pass\n", frameTimeTargetMs,
                kSpp, frames, midPass);
    if (frameTimeTargetMs > 0.0)
        EXPECT_GT(midPass, kSpp) << "passes were spread over frames";
    else
        EXPECT_EQ(midPass, 0) << "whole passes";
    EXPECT_EQ(view.stats().pathSamples, kSpp) << "the cap";
    EXPECT_TRUE(view.stats().settled) << "at the cap the viewport idles";
    view.render(p, v, kW, kH);
    EXPECT_EQ(view.stats().pathSamples, kSpp);
    EXPECT_EQ(view.stats().renderMs, 0.0) << "no samples past the cap";
    const PathImage viewport = view.pathTracer()->image();

    // The export: `fraktal render --mode path` at the same size and spp.
    // A folder of this process's own: the test's cases may run at once in parallel shards.
    const test::Sandbox box("fraktal_editor_pathtrace");
    const std::filesystem::path dir = box.dir;
    PathJob job;
    job.still.preset = p;
    job.still.preset.render.width = kW;
    job.still.preset.render.height = kH;
    job.still.preset.render.spp = kSpp;
    job.still.exr = dir / "still.exr";
    job.presetFile = presetFile();
    renderPathJob(job, color);
    const PathImage still = readExrBeauty(job.still.exr);
    ASSERT_EQ(still.width, kW);
    ASSERT_EQ(still.height, kH);

    // Same samples (sample k of a pixel draws the same random numbers in both): only the order of
    // the float sums differs (the viewport adds one sample per draw, the still four).
    const double psnr = meanImagePsnr(viewport, still);
    double worst = 0.0, coverage = 0.0;
    for (size_t i = 0; i < still.passes[kBeauty].size(); ++i) {
        if (i % 4 == 3)
            coverage += still.passes[kBeauty][i] / (kW * kH);
        else
            worst = std::max(worst, double(std::abs(viewport.passes[kBeauty][i] - still.passes[kBeauty][i])));
    }
    std::printf(
        "viewport at rest vs path export, %dx%d at %d spp: PSNR %.1f dB, largest difference %.2g, coverage %.2f\n", kW,
        kH, kSpp, psnr, worst, coverage);
    EXPECT_GE(psnr, 35.0);
    EXPECT_LT(worst, 1e-3);
    EXPECT_GT(coverage, 0.1) << "the fractal is in view";

    // What the viewport shows is the export's PNG: the same display transform of the same data
    // (rows in the same order, divided by the sample count).
    std::vector<uint8_t> png(size_t(kW) * kH * 3);
    DisplayTransform(color, color.resolveSpace(p.render.workingSpace), p.render.display, p.render.view,
                     p.render.exposure)
        .toDisplay8(still.passes[kBeauty], png);
    ASSERT_EQ(view.width(), kW);
    ASSERT_EQ(view.height(), kH);
    std::vector<uint8_t> shown(size_t(kW) * kH * 4);
    glGetTextureImage(view.displayTexture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(shown.size()), shown.data());
    int levels = 0, spreadLo = 255, spreadHi = 0;
    for (size_t i = 0; i < size_t(kW) * kH; ++i)
        for (int c = 0; c < 3; ++c) {
            levels = std::max(levels, std::abs(int(shown[i * 4 + c]) - int(png[i * 3 + c])));
            spreadLo = std::min(spreadLo, int(png[i * 3 + c]));
            spreadHi = std::max(spreadHi, int(png[i * 3 + c]));
        }
    EXPECT_LE(levels, 1) << "8-bit levels between the viewport and the export's PNG";
    EXPECT_GT(spreadHi - spreadLo, 64) << "an image, not a flat one";
}

TEST(EditorPathTrace, AtRestTheViewportShowsWhatThePathExportWrites) { expectViewportEqualsExport(0.0); }

TEST(EditorPathTrace, SamplePassesSpreadOverFramesGiveTheSameImage) { expectViewportEqualsExport(0.5); }

// The viewport resolves the scene every time its view rests: the environment map is loaded again
// only when its settings, the preset file or the working space changed.
TEST(EditorPathTrace, TheSceneReusesTheLoadedEnvironmentMapOnlyForTheSameSettings) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    Preset p = litMandelbulb();
    PathSceneData first = resolvePathScene(p, presetFile(), color);
    ASSERT_FALSE(first.environment.empty());
    first.environment.rgb[0] = -1.0f;  // no load gives a negative radiance: marks this copy
    p.camera.position.x += 1.0;
    p.lighting.lights.back().intensity = 3.0;
    EXPECT_EQ(resolvePathScene(p, presetFile(), color, &first).environment.rgb[0], -1.0f);
    p.lighting.environment.intensity = 2.0;
    const PathSceneData brighter = resolvePathScene(p, presetFile(), color, &first);
    EXPECT_GT(brighter.environment.rgb[0], 0.0f);
    p.lighting.environment.intensity = 1.0;
    const std::string otherFile = (test::sourceDir() / "presets" / "menger.json").string();
    EXPECT_GT(resolvePathScene(p, otherFile, color, &first).environment.rgb[0], 0.0f);
    p.lighting.environment.map.clear();
    EXPECT_TRUE(resolvePathScene(p, presetFile(), color, &first).environment.empty());
}

TEST(EditorPathTrace, AnyChangeDropsTheAccumulationToTheFastMode) {
    test::glContext();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    Preset p = litMandelbulb();
    CoreViewportView view(color);
    view.setPresetFile(presetFile());
    ViewSettings v = pathSettings();
    v.pathSppCap = 3;
    ASSERT_GT(renderUntilPathSpp(view, p, v, 3), 0) << view.compileError() << view.displayError();

    // A camera move: the next frame is the fast mode's, the count back to 0.
    p.camera.position.x += 0.05;
    view.render(p, v, kW, kH);
    EXPECT_FALSE(view.stats().pathTracing);
    EXPECT_EQ(view.stats().pathSamples, 0);
    EXPECT_FALSE(view.stats().settled);
    // At rest again it starts over from 0 samples.
    ASSERT_GT(renderUntilPathSpp(view, p, v, 1), 0);
    EXPECT_EQ(view.stats().pathSamples, 1);

    // A light the fast mode does not see drops it too; so do a parameter and the mode itself.
    ASSERT_GT(renderUntilPathSpp(view, p, v, 3), 0);
    p.lighting.lights.back().intensity *= 2.0;
    view.render(p, v, kW, kH);
    EXPECT_EQ(view.stats().pathSamples, 0);
    ASSERT_GT(renderUntilPathSpp(view, p, v, 3), 0);
    p.formula.nodes[0].values[0].x += 0.5;
    view.render(p, v, kW, kH);
    EXPECT_EQ(view.stats().pathSamples, 0);
    ASSERT_GT(renderUntilPathSpp(view, p, v, 3), 0);
    v.pathTraceAtRest = false;
    for (int i = 0; i < 5; ++i) {
        view.render(p, v, kW, kH);
        EXPECT_FALSE(view.stats().pathTracing);
    }
}

}  // namespace
}  // namespace fraktal::editor
