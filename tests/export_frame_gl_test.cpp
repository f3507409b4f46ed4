// The export frame guide on llvmpipe: a still export (the renderer `fraktal render` and the
// editor's export run) of a size whose aspect differs from the viewport's shows exactly what the
// viewport shows inside the guide (app/editor/viewport/export_frame.hpp), for an export wider and one
// narrower than the viewport. The guide's pixels are chosen to fall on whole viewport pixels, so
// the two images compare pixel for pixel.
#include <gtest/gtest.h>

#include "app/editor/viewport/export_frame.hpp"
#include "core/render/still_renderer.hpp"
#include "core/viewport/converge.hpp"
#include "core/viewport/image_error.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

constexpr int kViewW = 128, kViewH = 96;

std::vector<float> renderStill(const Preset& preset, int width, int height) {
    RenderSettings r = preset.render;
    r.width = width;
    r.height = height;
    r.spp = 1;
    gl::StillRenderer renderer(preset.formula, 128);
    renderer.setScene(preset.formula, preset.camera, r, resolveShading(preset.shading, r, preset.formula));
    ImageStrip image;
    image.resize(width, 0, height);
    for (const TileRect& tile : tilesOf({0, 0, width, height}, 128)) renderer.renderTile(tile, image);
    return image.rgba;
}

// The viewport (one sample per pixel, settled) with the camera the editor gives it for this
// export aspect, cropped to the guide.
std::vector<float> viewportInsideGuide(const Preset& preset, double exportAspect, bool widen = true) {
    const ExportFrame f = exportFrameInView(double(kViewW) / kViewH, exportAspect, preset.camera.fovY);
    Camera camera = preset.camera;
    if (widen) camera.fovY = f.viewFovY;
    viewport::ViewportOptions options;
    options.maxSamples = 1;
    viewport::Viewport view(options);
    const viewport::Converged c =
        viewport::renderUntilSettled(view, preset.formula, camera, preset.render, preset.shading, kViewW, kViewH, 400);
    EXPECT_TRUE(c.settled);
    const int x0 = int(std::lround(f.left * kViewW)), x1 = int(std::lround(f.right * kViewW));
    const int y0 = int(std::lround(f.top * kViewH)), y1 = int(std::lround(f.bottom * kViewH));
    std::vector<float> crop;
    for (int y = y0; y < y1; ++y)
        crop.insert(crop.end(), c.image.begin() + (size_t(y) * kViewW + x0) * 4,
                    c.image.begin() + (size_t(y) * kViewW + x1) * 4);
    return crop;
}

TEST(ExportFrameGL, StillExportShowsWhatTheGuideFrames) {
    test::glContext();
    const Preset preset = loadPreset(test::sourceDir() / "presets" / "mandelbulb.json");
    // 2:1 (wider than the 4:3 viewport: the guide is rows 16..80) and 1:1 (narrower: columns 16..112).
    const double wide = viewport::displayPsnr(viewportInsideGuide(preset, 2.0), renderStill(preset, 128, 64));
    const double square = viewport::displayPsnr(viewportInsideGuide(preset, 1.0), renderStill(preset, 96, 96));
    std::printf("inside the guide vs the export: 2:1 %.1f dB, 1:1 %.1f dB\n", wide, square);
    EXPECT_GE(wide, 30.0);
    EXPECT_GE(square, 30.0);
    // Without widening the view, a wider export shows more than the viewport's band: no match.
    const double unwidened =
        viewport::displayPsnr(viewportInsideGuide(preset, 2.0, false), renderStill(preset, 128, 64));
    EXPECT_LT(unwidened, wide - 6.0);
}

}  // namespace
}  // namespace fraktal::editor
