// The viewport on llvmpipe: equivalence with a fresh render after motion, silhouettes without
// holes, work saved by reprojection, and the cost of a settled frame. Small images: llvmpipe is slow.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "core/cpu_render/cpu_renderer.hpp"
#include "core/shading_params.hpp"
#include "core/viewport/camera_path.hpp"
#include "core/viewport/converge.hpp"
#include "core/viewport/flight.hpp"
#include "core/viewport/image_error.hpp"
#include "core/viewport/viewport.hpp"
#include "core/viewport/warm_up.hpp"
#include "test_support.hpp"
#include "uniform_lookups.hpp"

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

// An orbit of 12 reprojected frames, then the camera stops: the settled image of the moving
// viewport, the fresh viewport's for the same view, and that view.
struct AfterOrbit {
    Converged settled;
    std::vector<float> fresh;
    Camera camera;
};

AfterOrbit orbitThenSettle(const Scene& s, const ViewportOptions& options) {
    AfterOrbit a;
    Viewport moving(options);
    a.camera = s.preset.camera;
    for (int f = 0; f <= 12; ++f) {
        a.camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 1.0);
        moving.render(s.preset.formula, a.camera, s.render, s.preset.shading, kW, kH);
    }
    a.settled = renderUntilSettled(moving, s.preset.formula, a.camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
    a.fresh = freshRender(s, a.camera, options);
    return a;
}

// After an orbit of reprojected frames the camera stops; the progressive image must converge to
// what a fresh viewport renders for that view.
TEST(ViewportGL, ReprojectedImageConvergesToFreshRenderForEveryPreset) {
    test::glContext();
    ViewportOptions options;
    options.maxSamples = 4;
    for (const auto& path : test::shippedPresets()) {
        SCOPED_TRACE(path.filename().string());
        const AfterOrbit a = orbitThenSettle(loadScene(path), options);
        ASSERT_TRUE(a.settled.settled);
        EXPECT_GE(displayPsnr(a.settled.image, a.fresh), 40.0);
    }
}

// The same through the wide projections: reprojection inverts each (projectDirection in
// shaders/camera.glsl), so an orbit's carried image converges to a fresh one.
TEST(ViewportGL, ReprojectedImageConvergesToFreshRenderThroughWideProjections) {
    test::glContext();
    ViewportOptions options;
    options.maxSamples = 4;
    Scene s = loadScene(test::sourceDir() / "presets/mandelbulb.json");
    s.preset.camera.position = normalize(s.preset.camera.position) * 1.6;
    s.preset.camera.fovY = 180.0;
    for (Projection projection : {Projection::FishEye, Projection::Equirectangular}) {
        SCOPED_TRACE(kProjectionNames[int(projection)]);
        s.preset.camera.projection = projection;
        const AfterOrbit a = orbitThenSettle(s, options);
        ASSERT_TRUE(a.settled.settled);
        const Camera& camera = a.camera;
        const Converged& settled = a.settled;
        const double p = displayPsnr(settled.image, a.fresh);
        // The viewport draws the projection the CPU reference draws: the same share of hits.
        RenderSettings r = s.render;
        r.width = kW;
        r.height = kH;
        const ImageStrip cpu =
            renderReference(s.preset.formula, camera, r, resolveShading(s.preset.shading, r, s.preset.formula));
        Camera pinhole = camera;
        pinhole.projection = Projection::Perspective;
        pinhole.fovY = 120.0;
        const ImageStrip pinholeCpu =
            renderReference(s.preset.formula, pinhole, r, resolveShading(s.preset.shading, r, s.preset.formula));
        const double same = displayPsnr(settled.image, cpu.rgba), other = displayPsnr(settled.image, pinholeCpu.rgba);
        std::printf(
            "%s: settled after an orbit against fresh, PSNR %.1f dB; against the CPU reference %.1f dB "
            "(%.1f dB against a pinhole's)\n",
            kProjectionNames[int(projection)].data(), p, same, other);
        EXPECT_GE(p, 40.0);
        EXPECT_GT(same, other + 6.0);
    }
}

// The view distance in the viewport: its settled image is the CPU reference's with the same
// limit (the Mandelbulb cut at the median depth of its hits), not the uncut one's.
TEST(ViewportGL, CameraRaysEndAtTheViewDistanceAsInTheStill) {
    test::glContext();
    Scene s = loadScene(test::sourceDir() / "presets/mandelbulb.json");
    RenderSettings r = s.render;
    r.width = kW;
    r.height = kH;
    r.spp = 4;
    const ImageStrip uncut =
        renderReference(s.preset.formula, s.preset.camera, r, resolveShading(s.preset.shading, r, s.preset.formula));
    const std::vector<float> depths = test::hitDepths(uncut);
    ASSERT_GT(depths.size(), 100u);
    s.render.viewDistance = r.viewDistance = depths[depths.size() / 2];
    const ImageStrip cut =
        renderReference(s.preset.formula, s.preset.camera, r, resolveShading(s.preset.shading, r, s.preset.formula));
    const std::vector<float> settled = freshRender(s, s.preset.camera);
    const double same = displayPsnr(settled, cut.rgba), other = displayPsnr(settled, uncut.rgba);
    std::printf("settled viewport at view distance %.3f: against the cut CPU reference %.1f dB, the uncut %.1f dB\n",
                r.viewDistance, same, other);
    EXPECT_GT(same, other + 6.0);
}

// Where the moving viewport's centre rays found a different first surface than a fresh render's
// ("different": more than 8 pixel footprints apart; hits on the same surface agree to within the
// hit band). A hole: the fresh ray hit and the moving one escaped or hit farther, the failure a
// start reprojected past a surface causes. A phantom: the moving ray hit nearer, or where the
// fresh one escaped. Colours are not compared: under motion they are carried samples from
// elsewhere in the pixel, which differ on a fractal's sub-pixel texture.
struct SurfaceDifferences {
    double holes = 0.0, phantoms = 0.0;  // shares of the pixels
};

SurfaceDifferences compareSurfaces(const std::vector<float>& moving, const std::vector<float>& fresh,
                                   double pixelAngle) {
    constexpr float kHit = 1.0f;
    constexpr float kNowhere = 1e30f;
    size_t holes = 0, phantoms = 0;
    for (size_t i = 0; i + 3 < fresh.size(); i += 4) {
        const float freshT = fresh[i + 1] == kHit ? fresh[i] : kNowhere;
        const float movingT = moving[i + 1] == kHit ? moving[i] : kNowhere;
        const float apart = float(8.0 * pixelAngle * std::min(freshT, movingT));
        if (movingT > freshT + apart) ++holes;
        if (freshT > movingT + apart) ++phantoms;
    }
    const double pixels = double(fresh.size() / 4);
    return {double(holes) / pixels, double(phantoms) / pixels};
}

// No holes at silhouettes: views full of thin structures (the Sierpinski tetrahedron, the Menger
// sponge, the hybrid) are flown with reprojection at 2 degrees per frame, every frame marched to
// completion from its reprojected starts (steps per frame = max steps), and after each move the
// first surface of every pixel's centre ray is compared with a fresh render's.
// What is measured (summed over the 6 frames, Sierpinski / Menger / hybrid at 96x64): with the
// default coarse hits, holes 0.08 / 0.10 / 0.05 % of the pixels and phantoms 9.0 / 5.5 / 8.9 %:
// a coarse hit stops within two footprints of a thin part the full march goes past
// (ViewportOptions::coarseHits), so phantoms here mostly measure that, and the holes share is the
// assertion that bites. With coarse hits off: holes 0.81 / 0.37 / 0.33 %, phantoms 1.1 / 0.24 /
// 0.24 %, parts thinner than a pixel that only one of the two marches happened to touch. A
// systematic hole, such as a start past a surface or an eroded silhouette, would show as holes far
// outnumbering phantoms, or as a larger share.
TEST(ViewportGL, ReprojectedSilhouettesHaveNoHoles) {
    test::glContext();
    for (const char* name : {"sierpinski_tetrahedron.json", "menger.json", "hybrid_menger_octahedral.json"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(test::sourceDir() / "presets" / name);
        ViewportOptions options;
        options.stepsPerFrame = s.render.maxSteps;
        options.maxSamples = 1;
        ViewportOptions freshOptions = options;
        freshOptions.reproject = false;
        Viewport moving(options);
        int reprojectedFrames = 0;
        double holes = 0.0, phantoms = 0.0;
        for (int f = 0; f <= 6; ++f) {
            const Camera camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 2.0);
            const FrameStats stats = moving.render(s.preset.formula, camera, s.render, s.preset.shading, kW, kH);
            if (stats.action != FrameAction::Reproject) continue;
            ++reprojectedFrames;
            EXPECT_GT(stats.shareReprojected, 0.3) << "frame " << f << ": reprojection carried little over";
            Viewport fresh(freshOptions);
            renderUntilSettled(fresh, s.preset.formula, camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
            const double pixelAngle = camera.pixelAngle(kH);
            const SurfaceDifferences d = compareSurfaces(moving.readCentreRays(), fresh.readCentreRays(), pixelAngle);
            EXPECT_LT(d.holes, 0.006) << "frame " << f;
            holes += d.holes;
            phantoms += d.phantoms;
        }
        EXPECT_EQ(reprojectedFrames, 6);
        EXPECT_LE(holes, 1.5 * phantoms + 0.002) << "holes " << holes << ", phantoms " << phantoms << " (sums)";
    }
}

// The first frame of motion after rest moves onto a grid several times smaller (the editor's
// dynamic resolution), and the reprojection scatters blocks of the old grid's points
// (reprojectBlock): one point per block at its nearest distance, less the block's spread. That
// point must stay a lower bound: the small grid's rays start short of the surface a fresh render
// finds (one step on from their starts, within two pixel footprints), and marched to completion
// they find the same surfaces (no holes, as above), on grids an eighth and a quarter the side
// (blocks of 4 and 2 pixels). Measured: no start past the surface on the three scenes; a block
// that took its farthest distance instead starts 0.29 % of the Sierpinski tetrahedron's pixels past it.
TEST(ViewportGL, FirstMoveOntoASmallerGridHasNoHoles) {
    test::glContext();
    constexpr int kSmallW = 60, kSmallH = 40;
    for (const char* name : {"sierpinski_tetrahedron.json", "menger.json", "hybrid_menger_octahedral.json"})
        for (int ratio : {8, 4}) {
            SCOPED_TRACE(std::string(name) + ", ratio " + std::to_string(ratio));
            ASSERT_EQ(reprojectBlock(ratio * kSmallW, ratio * kSmallH, kSmallW, kSmallH), ratio / 2);
            const Scene s = loadScene(test::sourceDir() / "presets" / name);
            ViewportOptions options;
            options.maxSamples = 1;
            options.stepsPerFrame = s.render.maxSteps;
            ViewportOptions freshOptions = options;
            freshOptions.reproject = false;
            Viewport moving(options);
            ASSERT_TRUE(renderUntilSettled(moving, s.preset.formula, s.preset.camera, s.render, s.preset.shading,
                                           ratio * kSmallW, ratio * kSmallH, kMaxFrames)
                            .settled);
            const Camera camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, 1, 2.0);
            Viewport fresh(freshOptions);
            ASSERT_TRUE(renderUntilSettled(fresh, s.preset.formula, camera, s.render, s.preset.shading, kSmallW,
                                           kSmallH, kMaxFrames)
                            .settled);
            const std::vector<float> freshRays = fresh.readCentreRays();
            // The move, one step a ray: where each ray starts (one step on from its start).
            options.stepsPerFrame = 1;
            moving.setOptions(options);
            const FrameStats stats =
                moving.render(s.preset.formula, camera, s.render, s.preset.shading, kSmallW, kSmallH);
            ASSERT_EQ(stats.action, FrameAction::Reproject);
            EXPECT_GT(stats.shareReprojected, 0.3);
            const std::vector<float> starts = moving.readCentreRays();
            const double pixelAngle = camera.pixelAngle(kSmallH);
            size_t past = 0;
            for (size_t i = 0; i + 3 < freshRays.size(); i += 4)
                if (freshRays[i + 1] == 1.0f && starts[i] > freshRays[i] + 2.0 * pixelAngle * freshRays[i]) ++past;
            const double pastShare = double(past) / double(kSmallW * kSmallH);
            // Then marched to completion in the next frame (held: the camera has not been seen to
            // stop yet, so it marches on rather than restarting at full quality).
            options.stepsPerFrame = s.render.maxSteps;
            moving.setOptions(options);
            const FrameStats held =
                moving.render(s.preset.formula, camera, s.render, s.preset.shading, kSmallW, kSmallH);
            ASSERT_EQ(held.action, FrameAction::Hold);
            const SurfaceDifferences d = compareSurfaces(moving.readCentreRays(), freshRays, pixelAngle);
            std::printf("%s, ratio %d: starts past the surface %.2f %%, holes %.2f %%, phantoms %.2f %%\n", name, ratio,
                        100.0 * pastShare, 100.0 * d.holes, 100.0 * d.phantoms);
            EXPECT_LT(pastShare, 0.002);
            EXPECT_LT(d.holes, 0.006);
            EXPECT_LE(d.holes, 1.5 * d.phantoms + 0.002);
        }
}

// The camera stops after motion on a smaller grid, and the caller slices the first frame at rest
// at full size: that frame starts the view afresh, sliced (a reset), instead of reprojecting the
// small grid and marching every ray of the full view in one frame (650-700 ms on light scenes in
// the editor on llvmpipe). Unsliced, the size change under motion still reprojects.
TEST(ViewportGL, AFrameAtRestAfterMotionOnASmallerGridIsASlicedReset) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "mandelbulb.json");
    for (int slices : {4, 1}) {
        SCOPED_TRACE("slices " + std::to_string(slices));
        ViewportOptions options;
        Viewport v(options);
        renderUntilSettled(v, s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
        const Camera moved = cameraOnPath(s.preset.camera, CameraPath::Orbit, 1, 1.0);
        ASSERT_EQ(v.render(s.preset.formula, moved, s.render, s.preset.shading, kW / 4, kH / 4).action,
                  FrameAction::Reproject);
        options.slices = slices;
        v.setOptions(options);
        const FrameStats atRest = v.render(s.preset.formula, moved, s.render, s.preset.shading, kW, kH);
        EXPECT_EQ(atRest.action, slices > 1 ? FrameAction::Reset : FrameAction::Reproject);
        EXPECT_EQ(atRest.slices, slices);
    }
}

// A grid made ahead (the editor's worker makes the full-size one, its memory written there) is the
// one the first frame at its size uses, and the view it refines is the same to the bit as on a grid
// the viewport made itself, from the small first picture on: a grid written whole (touchAll) holds
// nothing a frame reads before writing it. One of another cone tile is not taken.
TEST(ViewportGL, AGridMadeAheadRendersAsTheViewportsOwn) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "mandelbulb.json");
    std::vector<float> images[2], moves[2];
    for (int ahead : {0, 1}) {
        SCOPED_TRACE(ahead ? "made ahead" : "the viewport's own");
        ViewportOptions options;
        options.slices = 4;
        Viewport v(options);
        v.render(s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW / 8, kH / 8);
        EXPECT_FALSE(v.hasGrid(kW, kH));
        if (ahead) {
            v.adoptSpareGrid(std::make_unique<MarchState>(kW, kH, options.coneTile + 8));
            EXPECT_FALSE(v.hasGrid(kW, kH)) << "a grid of another cone tile";
            auto grid = std::make_unique<MarchState>(kW, kH, options.coneTile);
            grid->touchAll();
            v.adoptSpareGrid(std::move(grid));
            EXPECT_TRUE(v.hasGrid(kW, kH));
        }
        renderUntilSettled(v, s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH, kMaxFrames);
        images[ahead] = v.readImage();
        // And a moved frame on it, which reprojects the settled view.
        const Camera moved = cameraOnPath(s.preset.camera, CameraPath::Orbit, 1, 1.0);
        EXPECT_EQ(v.render(s.preset.formula, moved, s.render, s.preset.shading, kW, kH).action, FrameAction::Reproject);
        moves[ahead] = v.readImage();
    }
    ASSERT_FALSE(images[0].empty());
    EXPECT_EQ(images[0], images[1]);
    EXPECT_EQ(moves[0], moves[1]);
}

// Every colour the viewport holds, fresh or carried by reprojection, is the shading of a point on
// the surface: the point its colourPoint names lies within the hit band of the formula's CPU DE.
// Reprojection scatters colours by these points and the motion filter places samples at them, so
// a point off the surface (a store into the wrong image, a stale point kept with a new colour)
// moves colours to where they do not belong.
TEST(ViewportGL, ColourPointsLieOnTheSurface) {
    test::glContext();
    for (const char* name : {"menger.json", "mandelbulb.json"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(test::sourceDir() / "presets" / name);
        Viewport viewport;
        for (int f = 0; f <= 3; ++f) {
            const Camera camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 2.0);
            viewport.render(s.preset.formula, camera, s.render, s.preset.shading, kW, kH);
            const double pixelAngle = camera.pixelAngle(kH);
            const double detail = std::max(s.render.detail, 1.0);
            const std::vector<float> points = viewport.readColourPoints();
            int surface = 0, within2 = 0;
            double worst = 0.0;
            for (size_t i = 0; i + 3 < points.size(); i += 4) {
                if (points[i + 3] == 0.0f) continue;
                const vec3 p(points[i], points[i + 1], points[i + 2]);
                const double footprint = pixelAngle * glm::length(p - camera.position) * detail;
                const double d = std::abs(distanceEstimate(s.preset.formula, p)) / footprint;
                ++surface;
                if (d < 2.0) ++within2;
                worst = std::max(worst, d);
            }
            EXPECT_GT(surface, kW * kH / 10) << "frame " << f << ": few surface colours";
            // Out-of-steps hits (a ray crawling along a grazing surface) may stop up to 10
            // footprints away. Measured at 320x180 over the same 4 frames: every point within
            // 1.5 footprints (Menger) and 0.8 (Mandelbulb).
            EXPECT_GE(within2, 0.99 * surface) << "frame " << f;
            EXPECT_LT(worst, 12.0) << "frame " << f;
        }
    }
}

// Speed as work: over the orbit path with 30 steps per frame, reprojection needs far fewer DE
// evaluations per pixel per frame (shading included) than restarting every ray, with an image at
// least as close to the fully converged (anti-aliased) render of each view. The target was
// 5x; measured here 4.4x (14.8 against 3.4 DE per pixel per frame; 16 frames from an empty
// viewport, whose first frame restarts every ray in both modes). Before the adaptive step
// (shaders/march.glsl) it was 4.7x (14.7 against 3.1, `fraktal bench viewport --frames 16
// --degrees 1 --size 240x135 --steps 30 --samples 4`): reprojected rays start within a few
// thresholds of the surface, where a verified step must leave a threshold of overlap and more of
// the first relaxed steps are taken back. The test holds the line at 4x (bench/README.md has every
// preset). Small images favour restarting (30 steps finish nearly every ray at 96x64), hence
// 240x135.
TEST(ViewportGL, ReprojectionCutsDeEvaluationsAtEqualOrBetterError) {
    test::glContext();
    const Preset preset = loadPreset(test::sourceDir() / "presets" / "mandelbulb.json");
    FlightSettings fs;
    fs.frames = 16;
    fs.degreesPerFrame = 1.0;
    fs.width = 240;
    fs.height = 135;
    fs.options.stepsPerFrame = 30;
    fs.options.maxSamples = 4;  // the reference: the view settled at 4 samples per pixel
    FlightSettings restart = fs;
    restart.options.reproject = false;
    const FlightResult withReprojection = fly(preset, fs);
    const FlightResult withRestarts = fly(preset, restart);
    EXPECT_GE(withRestarts.meanDeEvalsPerPixel, 4.0 * withReprojection.meanDeEvalsPerPixel)
        << "reproject " << withReprojection.meanDeEvalsPerPixel << " vs restart " << withRestarts.meanDeEvalsPerPixel;
    EXPECT_GE(withReprojection.meanPsnrDb, withRestarts.meanPsnrDb)
        << "reproject " << withReprojection.meanPsnrDb << " dB vs restart " << withRestarts.meanPsnrDb << " dB";
}

// Dynamic resolution changes the grid's size while the camera moves: down by any factor (a slow
// frame drops the scale at once), up by one step of the controller at a time (1/16 of the full
// size; here 8 to 9). The previous grid's points are world points, so they scatter into the new
// grid: the frame after a size change costs far fewer DE evaluations than restarting every ray,
// and once the camera stops the view still converges to a fresh render. (A 2x magnification,
// which the controller never makes under motion, costs about half a restart: 3 in 4 pixels then
// get no carried colour and are shaded afresh.)
TEST(ViewportGL, SizeChangeUnderMotionReprojectsIntoTheNewGrid) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "mandelbulb.json");
    ViewportOptions options;
    options.maxSamples = 4;
    Viewport moving(options);
    Camera camera = s.preset.camera;
    int frame = 0;
    auto step = [&](int w, int h) {
        camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, frame++, 1.0);
        return moving.render(s.preset.formula, camera, s.render, s.preset.shading, w, h);
    };
    auto restartCost = [&](int w, int h) {
        Viewport fresh(options);
        return fresh.render(s.preset.formula, camera, s.render, s.preset.shading, w, h).deEvalsPerPixel;
    };
    const int fullW = 2 * kW, fullH = 2 * kH, upW = kW * 9 / 8, upH = kH * 9 / 8;
    for (int f = 0; f < 8; ++f) step(fullW, fullH);
    const FrameStats down = step(kW, kH);  // scale 1 to 0.5
    EXPECT_EQ(down.action, FrameAction::Reproject);
    const double downRestart = restartCost(kW, kH);
    for (int f = 0; f < 6; ++f) step(kW, kH);
    const FrameStats up = step(upW, upH);  // 0.5 to 0.5625
    EXPECT_EQ(up.action, FrameAction::Reproject);
    const double upRestart = restartCost(upW, upH);
    std::printf("DE per pixel after a size change: down %.2f (restart %.2f), up %.2f (restart %.2f)\n",
                down.deEvalsPerPixel, downRestart, up.deEvalsPerPixel, upRestart);
    EXPECT_LE(down.deEvalsPerPixel, 0.4 * downRestart);
    EXPECT_LE(up.deEvalsPerPixel, 0.4 * upRestart);
    // At rest at full size: the same image as a fresh render of the view.
    Converged settled =
        renderUntilSettled(moving, s.preset.formula, camera, s.render, s.preset.shading, fullW, fullH, kMaxFrames);
    ASSERT_TRUE(settled.settled);
    Viewport fresh(options);
    Converged reference =
        renderUntilSettled(fresh, s.preset.formula, camera, s.render, s.preset.shading, fullW, fullH, kMaxFrames);
    ASSERT_TRUE(reference.settled);
    EXPECT_GE(displayPsnr(settled.image, reference.image), 40.0);
}

// Once every pixel has its full AA (the cap), a frame of the unchanged view costs under 2 DE
// evaluations per pixel (it costs none: nothing is marched or shaded again).
// Restarting every ray, each finished sample lies at its pixel's centre. The motion filter at its
// default radius (one pixel) must then show those samples exactly as they are; a wider one blends
// each pixel with its neighbours, never outside the range of the 3x3 colours it reads.
TEST(ViewportGL, MotionFilterRadiusOfOnePixelLeavesCentreSamplesAlone) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "menger.json");
    auto movingImage = [&](bool filter, double radius) {
        ViewportOptions options;
        options.reproject = false;
        options.motionFilter = filter;
        options.motionFilterRadius = radius;
        Viewport v(options);
        for (int f = 0; f <= 1; ++f)
            v.render(s.preset.formula, cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 1.0), s.render,
                     s.preset.shading, kW, kH);
        return v.readImage();
    };
    const std::vector<float> unfiltered = movingImage(false, 1.0);
    const std::vector<float> onePixel = movingImage(true, 1.0);
    const std::vector<float> wider = movingImage(true, 1.75);
    ASSERT_EQ(onePixel.size(), unfiltered.size());
    // A hit's sample lies where its refined point projects: at the centre up to float rounding
    // (116 dB here), so its neighbours' weights are not exactly 0.
    EXPECT_GE(displayPsnr(onePixel, unfiltered), 90.0) << "a one-pixel tent blended samples at pixel centres";
    int blended = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x)
            for (int c = 0; c < 3; ++c) {
                float lo = 1e30f, hi = -1e30f;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const int qx = std::clamp(x + dx, 0, kW - 1), qy = std::clamp(y + dy, 0, kH - 1);
                        const float v = unfiltered[(size_t(qy) * kW + qx) * 4 + c];
                        lo = std::min(lo, v);
                        hi = std::max(hi, v);
                    }
                const float w = wider[(size_t(y) * kW + x) * 4 + c];
                ASSERT_GE(w, lo - 1e-5f * std::abs(lo)) << "pixel " << x << "," << y;
                ASSERT_LE(w, hi + 1e-5f * std::abs(hi)) << "pixel " << x << "," << y;
                if (w != unfiltered[(size_t(y) * kW + x) * 4 + c]) ++blended;
            }
    EXPECT_GT(blended, kW * kH / 10) << "a 1.75-pixel tent should blend most pixels with their neighbours";
}

// The march list (ViewportOptions::deferAfterSteps) only moves where a ray's later steps run on
// reprojected frames: from empty, under motion and while the AA level rises at rest, every
// frame's counts and image must be the same, bit for bit, however many steps the full-screen
// pass takes first.
TEST(ViewportGL, MarchListTakesTheSameStepsAsOneFullScreenPass) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "mandelbulb.json");
    struct Run {
        std::vector<FrameStats> stats;
        std::vector<std::vector<float>> images;
        double meanListed = 0.0;
    };
    auto renderFrames = [&](int deferAfterSteps) {
        ViewportOptions options;
        options.maxSamples = 4;
        options.deferAfterSteps = deferAfterSteps;
        Viewport v(options);
        Run run;
        constexpr int kMoving = 5, kFrames = 12;
        for (int f = 0; f < kFrames; ++f) {
            const Camera camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, std::min(f, kMoving), 1.0);
            run.stats.push_back(v.render(s.preset.formula, camera, s.render, s.preset.shading, kW, kH));
            run.images.push_back(v.readImage());
            run.meanListed += run.stats.back().shareMarchListed / kFrames;
        }
        return run;
    };
    const Run whole = renderFrames(0);
    EXPECT_EQ(whole.meanListed, 0.0) << "with deferAfterSteps 0 no ray goes on the march list";
    for (int deferAfter : {1, 6}) {
        const Run split = renderFrames(deferAfter);
        EXPECT_GT(split.meanListed, 0.0) << "no ray went on the march list after " << deferAfter << " steps";
        for (size_t f = 0; f < whole.stats.size(); ++f) {
            SCOPED_TRACE("defer after " + std::to_string(deferAfter) + ", frame " + std::to_string(f));
            const FrameStats &a = whole.stats[f], &b = split.stats[f];
            EXPECT_EQ(a.action, b.action);
            EXPECT_EQ(a.deEvalsPerPixel, b.deEvalsPerPixel);
            EXPECT_EQ(a.shadeDeEvalsPerPixel, b.shadeDeEvalsPerPixel);
            EXPECT_EQ(a.shareReprojected, b.shareReprojected);
            EXPECT_EQ(a.shareRestarted, b.shareRestarted);
            EXPECT_EQ(a.shareConverged, b.shareConverged);
            EXPECT_EQ(a.shareShaded, b.shareShaded);
            EXPECT_EQ(a.settled, b.settled);
            EXPECT_TRUE(whole.images[f] == split.images[f]) << "the images differ";
        }
    }
}

// Sliced refinement (ViewportOptions::slices): a reset and the frames at rest refine one slice of
// the view each. A pixel takes the same steps, shading and samples as with the whole view a frame,
// so the settled image is the same to the bit, from a reset and after an orbit (whose reprojected
// frames march the whole view); a sliced frame costs a fraction of a whole one.
TEST(ViewportGL, SlicedRefinementSettlesToTheSameImage) {
    test::glContext();
    for (const char* name : {"mandelbulb.json", "kleinian.json"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(test::sourceDir() / "presets" / name);
        ViewportOptions whole;
        whole.maxSamples = 4;
        const std::vector<float> reference = freshRender(s, s.preset.camera, whole);
        const AfterOrbit wholeOrbit = orbitThenSettle(s, whole);
        ASSERT_TRUE(wholeOrbit.settled.settled);
        for (int slices : {3, 4}) {
            SCOPED_TRACE("slices " + std::to_string(slices));
            ViewportOptions sliced = whole;
            sliced.slices = slices;
            Viewport v(sliced);
            const FrameStats first = v.render(s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH);
            EXPECT_EQ(first.slices, slices);
            Viewport w(whole);
            const FrameStats firstWhole =
                w.render(s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH);
            EXPECT_LT(first.deEvalsPerPixel, 0.6 * firstWhole.deEvalsPerPixel)
                << "a sliced reset marched the whole view";
            const Converged c = renderUntilSettled(v, s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW,
                                                   kH, slices * kMaxFrames);
            ASSERT_TRUE(c.settled);
            EXPECT_TRUE(c.image == reference) << "the sliced settled image differs from the whole one's";
            const AfterOrbit orbit = orbitThenSettle(s, sliced);
            ASSERT_TRUE(orbit.settled.settled);
            EXPECT_TRUE(orbit.settled.image == wholeOrbit.settled.image) << "after an orbit the settled images differ";
        }
    }
}

// The warm-up (core/viewport/warm_up.hpp) renders tiny frames with a structure's programs before
// the viewport gets them, and program uniforms are shared state: the viewport must set every one
// it reads each frame, never rely on what the warm-up left. So a viewport that adopts warmed-up
// programs settles, after an orbit too, to the same image to the bit as one that built its own.
TEST(ViewportGL, WarmedUpProgramsRenderTheSameImage) {
    test::glContext();
    for (const char* name : {"mandelbulb.json", "kleinian.json", "menger_objects.json"}) {
        SCOPED_TRACE(name);
        const Scene s = loadScene(test::sourceDir() / "presets" / name);
        ViewportOptions options;
        options.maxSamples = 4;
        options.coneTile = 8;
        Viewport own(options), warmed(options);
        warmed.adoptPrograms(warmUp(std::make_unique<ViewportPrograms>(s.preset.formula), s.preset.formula));
        for (Viewport* v : {&own, &warmed})
            for (int f = 0; f <= 6; ++f)
                v->render(s.preset.formula, cameraOnPath(s.preset.camera, CameraPath::Orbit, f, 1.0), s.render,
                          s.preset.shading, kW, kH);
        const Camera stopped = cameraOnPath(s.preset.camera, CameraPath::Orbit, 6, 1.0);
        const Converged a =
            renderUntilSettled(own, s.preset.formula, stopped, s.render, s.preset.shading, kW, kH, kMaxFrames);
        const Converged b =
            renderUntilSettled(warmed, s.preset.formula, stopped, s.render, s.preset.shading, kW, kH, kMaxFrames);
        ASSERT_TRUE(a.settled && b.settled);
        EXPECT_TRUE(a.image == b.image) << "the warmed-up programs settle to another image";
    }
}

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

// Uniform locations are found once per program when it is built: a frame, moving (reprojection,
// the march list, the motion filter) or at rest (accumulation), with the cone pre-pass and the
// display pass, looks none up.
TEST(ViewportGL, FramesLookUpNoUniformLocations) {
    test::glContext();
    const Scene s = loadScene(test::sourceDir() / "presets" / "mandelbox.json");
    ViewportOptions options;
    options.maxSamples = 4;
    options.coneTile = 8;
    Viewport v(options);
    GLuint target = 0, framebuffer = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &target);
    glTextureStorage2D(target, 1, GL_RGBA8, kW, kH);
    glCreateFramebuffers(1, &framebuffer);
    glNamedFramebufferTexture(framebuffer, GL_COLOR_ATTACHMENT0, target, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    glViewport(0, 0, kW, kH);
    v.render(s.preset.formula, s.preset.camera, s.render, s.preset.shading, kW, kH);  // builds the programs
    v.drawDisplay(0.0f);
    constexpr int kFrames = 12;
    int moving = 0;
    {
        const test::UniformLookups counter;
        for (int f = 1; f <= kFrames; ++f) {
            const Camera camera = cameraOnPath(s.preset.camera, CameraPath::Orbit, std::min(f, kFrames / 2), 1.0);
            moving +=
                v.render(s.preset.formula, camera, s.render, s.preset.shading, kW, kH).action == FrameAction::Reproject;
            v.drawDisplay(0.0f);
        }
        std::printf("%d frames (%d reprojected): %d uniform lookups, %.3f ms in them\n", kFrames, moving,
                    test::UniformLookups::calls, test::UniformLookups::seconds * 1e3);
        EXPECT_EQ(test::UniformLookups::calls, 0);
    }
    EXPECT_GE(moving, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &framebuffer);
    glDeleteTextures(1, &target);
}

}  // namespace
}  // namespace fraktal::viewport
