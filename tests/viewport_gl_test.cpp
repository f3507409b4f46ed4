// The viewport on llvmpipe: equivalence with a fresh render after motion, silhouettes without
// holes, work saved by reprojection, and the cost of a settled frame. Small images: llvmpipe is slow.
#include <gtest/gtest.h>

#include "core/viewport/camera_path.hpp"
#include "core/viewport/converge.hpp"
#include "core/viewport/flight.hpp"
#include "core/viewport/image_error.hpp"
#include "core/viewport/viewport.hpp"
#include "test_support.hpp"

namespace fraktal::viewport {
namespace {

constexpr int kW = 96, kH = 64;
constexpr int kMaxFrames = 400;

struct Scene {
    Preset preset;
    RenderSettings render;
};

Scene loadScene(const std::filesystem::path& path) {
    Scene s{loadPreset(path), {}};
    s.render = s.preset.render;
    return s;
}

std::vector<float> freshRender(const Scene& s, const Camera& camera, ViewportOptions options = {}) {
    Viewport fresh(options);
    Converged c = renderUntilSettled(fresh, s.preset.formula, camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
    EXPECT_TRUE(c.settled) << "fresh render did not settle in " << kMaxFrames << " frames";
    return c.image;
}

// After an orbit of reprojected frames the camera stops; the progressive image must converge to
// what a fresh viewport renders for that view.
TEST(ViewportGL, ReprojectedImageConvergesToFreshRenderForEveryPreset) {
    test::glContext();
    ViewportOptions options;
    options.maxSamples = 4;
    for (const auto& path : test::shippedPresets()) {
        SCOPED_TRACE(path.filename().string());
        const Scene s = loadScene(path);
        Viewport moving(options);
        Camera camera = s.preset.camera;
        for (int f = 0; f <= 12; ++f) {
            camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 1.0);
            moving.render(s.preset.formula, camera, s.render, s.preset.shading, kW, kH);
        }
        Converged settled =
            renderUntilSettled(moving, s.preset.formula, camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
        ASSERT_TRUE(settled.settled);
        const std::vector<float> reference = freshRender(s, camera, options);
        EXPECT_GE(displayPsnr(settled.image, reference), 40.0);
    }
}

// Once every pixel has its full AA (the cap), a frame of the unchanged view costs under 2 DE
// evaluations per pixel (it costs none: nothing is marched or shaded again).
TEST(ViewportGL, SettledFrameCostsUnderTwoDeEvaluationsPerPixel) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "mandelbox.json");
    ViewportOptions options;
    options.maxSamples = 4;
    Viewport v(options);
    const Converged c =
        renderUntilSettled(v, s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
    ASSERT_TRUE(c.settled);
    const FrameStats rest = v.render(s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH);
    EXPECT_TRUE(rest.settled);
    EXPECT_EQ(rest.action, FrameAction::Continue);
    EXPECT_LT(rest.deEvalsPerPixel, 2.0);
    EXPECT_GE(displayPsnr(v.readImage(), c.image), 99.0) << "a settled frame changed the image";
}

}  // namespace
}  // namespace fraktal::viewport
