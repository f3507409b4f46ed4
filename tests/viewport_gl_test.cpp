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

// Share of pixels whose display colours differ by more than a quarter of the range in some
// channel: a hole (background where the fresh render shows surface, or a far surface seen through
// a near one) changes a pixel that much; the hit band and reused colours do not.
double shareOfBrokenPixels(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    size_t broken = 0;
    for (size_t i = 0; i + 3 < a.size(); i += 4)
        for (int c = 0; c < 3; ++c)
            if (std::abs(int(a[i + c]) - int(b[i + c])) > 64) {
                ++broken;
                break;
            }
    return double(broken) / double(a.size() / 4);
}

// No holes at silhouettes: a view full of thin structures (the Sierpinski tetrahedron and the
// Menger sponge) is flown with reprojection, every frame marched to completion from its
// reprojected starts (steps per frame = max steps), and compared after each move with a fresh
// single-sample render of the same view. A start reprojected past a thin surface would show the
// background or a farther surface there.
TEST(ViewportGL, ReprojectedSilhouettesHaveNoHoles) {
    test::glContext();
    for (const char* name : {"sierpinski_tetrahedron.json", "menger.json"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(test::sourceDir() / "presets" / name);
        ViewportOptions options;
        options.stepsPerFrame = s.render.maxSteps;
        options.maxSamples = 1;
        ViewportOptions freshOptions = options;
        freshOptions.reproject = false;
        Viewport moving(options);
        int reprojectedFrames = 0;
        for (int f = 0; f <= 6; ++f) {
            const Camera camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 2.0);
            const FrameStats stats = moving.render(s.preset.formula, camera, s.render, s.preset.shading, kW, kH);
            if (stats.action != FrameAction::Reproject) continue;
            ++reprojectedFrames;
            EXPECT_GT(stats.shareReprojected, 0.3) << "frame " << f << ": reprojection carried little over";
            Viewport fresh(freshOptions);
            renderUntilSettled(fresh, s.preset.formula, camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
            EXPECT_LT(shareOfBrokenPixels(moving.readDisplay(0.0f), fresh.readDisplay(0.0f)), 0.002) << "frame " << f;
        }
        EXPECT_EQ(reprojectedFrames, 6);
    }
}

// Speed as work: over the orbit path with 30 steps per frame, reprojection needs at least 5x fewer
// DE evaluations per pixel per frame than restarting every ray, with an image at least as close
// to the converged render of each view (equal error or better).
TEST(ViewportGL, ReprojectionCutsDeEvaluationsFiveTimesAtEqualError) {
    test::glContext();
    const Preset preset = loadPreset(test::sourceDir() / "presets" / "mandelbulb.json");
    FlightSettings fs;
    fs.frames = 12;
    fs.degreesPerFrame = 1.0;
    fs.width = kW;
    fs.height = kH;
    fs.options.stepsPerFrame = 30;
    FlightSettings restart = fs;
    restart.options.reproject = false;
    const FlightResult withReprojection = fly(preset, fs);
    const FlightResult withRestarts = fly(preset, restart);
    EXPECT_GE(withRestarts.meanDeEvalsPerPixel, 5.0 * withReprojection.meanDeEvalsPerPixel)
        << "reproject " << withReprojection.meanDeEvalsPerPixel << " vs restart " << withRestarts.meanDeEvalsPerPixel;
    EXPECT_GE(withReprojection.meanPsnrDb, withRestarts.meanPsnrDb - 0.5);
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
