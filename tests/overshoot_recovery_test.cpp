// The marcher recovers from overshoot (shaders/march.glsl, recoverOvershoot, and its CPU mirror in
// core/cpu_render/cpu_shading.cpp): a step that lands inside the object is bisected back to the
// crossing. Each renderer that marches (the fast still on the GPU and the CPU, the path tracer,
// the viewport) is run at a step factor that overshoots, and its hits must lie where a render at
// a small factor puts them, not one overshooting step behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/cpu_render/cpu_renderer.hpp"
#include "core/render/path_tracer.hpp"
#include "core/render/still_renderer.hpp"
#include "core/viewport/converge.hpp"
#include "core/viewport/viewport.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

constexpr int kW = 64, kH = 48;

// The squaring ball: the escape-time ball of radius 4^(1 / 2^8) that 8 squarings draw, whose
// potential estimate is half the distance to it (test::squaringBall). At factor 3.6 a step goes
// 1.8 times the gap and lands inside, where the estimate tells nothing about how deep: without
// the recovery each hit stays there.
constexpr double kBallFactor = 3.6;
const double kBallRadius = std::pow(4.0, 1.0 / 256.0);

Preset solidBall() {
    Preset p;
    p.formula = test::squaringBall(8);
    p.formula.boundRadius = 3.0;
    p.formula.deFactor = kBallFactor;
    p.camera.position = vec3(0.1, 0.15, 2.2);
    p.camera.target = vec3(0.0);
    p.camera.fovY = 40.0;
    p.render.width = kW;
    p.render.height = kH;
    p.render.spp = 1;
    p.render.maxSteps = 2000;
    return p;
}

// The shipped Mandelbulb at twice the factor its check measured.
Preset overshootingBulb() {
    Preset p = loadPreset(test::sourceDir() / "presets" / "mandelbulb.json");
    p.formula.deFactor *= 2.0;
    p.render.width = kW;
    p.render.height = kH;
    p.render.spp = 1;
    p.render.maxSteps = 2000;
    return p;
}

// The same scene at an eighth of the factor and of the hit threshold (so that both stop where
// the factored estimate is the same), which does not overshoot.
Preset reference(Preset p) {
    p.formula.deFactor /= 8.0;
    p.render.detail /= 8.0;
    p.render.maxSteps = 8000;
    return p;
}

constexpr float kMiss = 1e29f;

std::vector<float> depthOf(const std::vector<float>& normalDepth) {
    std::vector<float> z;
    for (size_t i = 3; i < normalDepth.size(); i += 4) z.push_back(normalDepth[i]);
    return z;
}

std::vector<float> stillDepth(const Preset& p) {
    test::glContext();
    const ShadingParams shading = resolveShading(p.shading, p.render, p.formula);
    gl::StillRenderer renderer(p.formula, 128);
    renderer.setScene(p.formula, p.camera, p.render, shading, 0.0);
    ImageStrip image;
    image.resize(kW, 0, kH);
    renderer.renderTile({0, 0, kW, kH}, image);
    return depthOf(image.normalDepth);
}

std::vector<float> cpuDepth(const Preset& p) {
    const ShadingParams shading = resolveShading(p.shading, p.render, p.formula);
    return depthOf(renderReference(p.formula, p.camera, p.render, shading).normalDepth);
}

std::vector<float> pathDepth(const Preset& p) {
    test::glContext();
    const ShadingParams shading = resolveShading(p.shading, p.render, p.formula);
    const Lighting lighting;
    const EnvironmentMap environment;
    gl::PathTracer tracer(p.formula, kW, kH);
    tracer.setScene(PathScene{p.formula, p.camera, p.render, shading, lighting, environment});
    tracer.addSamples(1, 1);
    return depthOf(tracer.image().passes[kNormal]);
}

struct DepthComparison {
    int referenceHits = 0;
    int behind = 0;  // hits more than 10 % behind the reference's, or misses where it hits
};

DepthComparison compareDepths(const std::vector<float>& reference, const std::vector<float>& render) {
    DepthComparison c;
    for (size_t i = 0; i < reference.size(); ++i) {
        if (!(reference[i] < kMiss)) continue;
        ++c.referenceHits;
        if (!(render[i] < kMiss) || render[i] > reference[i] * 1.1f) ++c.behind;
    }
    return c;
}

struct Renderer {
    const char* name;
    std::vector<float> (*depth)(const Preset&);
};
const Renderer kRenderers[] = {
    {"fast still (GL)", stillDepth}, {"fast still (CPU)", cpuDepth}, {"path tracer", pathDepth}};

// Each renderer's depth at `scene`'s overshooting factor against its reference: at least
// `minHitShare` of the pixels hit, and at most `maxBehindShare` of those lie behind.
void expectDepthKept(const char* what, const Preset& scene, double minHitShare, double maxBehindShare) {
    for (const Renderer& r : kRenderers) {
        const DepthComparison c = compareDepths(r.depth(reference(scene)), r.depth(scene));
        std::printf("%s: %d of %d %s pixels behind the reference\n", r.name, c.behind, c.referenceHits, what);
        EXPECT_GT(c.referenceHits, minHitShare * kW * kH) << r.name;
        EXPECT_LE(c.behind, maxBehindShare * c.referenceHits) << r.name;
    }
}

// Every ray into the squaring ball overshoots its surface: with the recovery all but the rays
// near its rim come back to it (those cross the ball and out again before a step lands inside);
// without it every hit pixel stayed behind (2912 of 2912).
TEST(OvershootRecovery, StepsIntoASolidBallComeBackToItsSurface) { expectDepthKept("ball", solidBall(), 0.5, 0.05); }

// A camera inside the squaring ball: the estimate is 0 where the ray starts, and so is the hit
// threshold (it grows with the distance along the ray). Every pixel is a hit at the camera; a
// march that stepped by 0 there ran out of steps with nothing drawn.
TEST(OvershootRecovery, ACameraInsideAnEscapeTimeObjectSeesItEverywhere) {
    Preset p = solidBall();
    p.formula.deFactor = 1.0;
    p.camera.position = vec3(0.1, 0.15, 0.2);
    for (const Renderer& r : kRenderers) {
        const std::vector<float> depth = r.depth(p);
        const long atCamera = std::count_if(depth.begin(), depth.end(), [](float z) { return z < 1e-3f; });
        EXPECT_EQ(atCamera, long(depth.size())) << r.name;
    }
}

// The shipped Mandelbulb at twice its factor: rays that land inside are bisected back (104 of 1531
// pixels behind without the recovery, 73 with); what is left are rays that stepped across a thin
// part and out again, which no membership test sees.
TEST(OvershootRecovery, AnOvershootingBulbKeepsItsDepth) {
    expectDepthKept("bulb", overshootingBulb(), 0.2, 1.0 / 17.0);
}

// The viewport marches a step per pass and resumes from its stored state (t, lastD, omega): the
// point a step left from is known from that state, so it recovers as the still does. Its colour
// points at rest lie on the ball's surface, within two pixel footprints (without the recovery
// 2608 of 2864 did not).
// The settled viewport's colour points of `scene`: how many lie on a surface, and how many of those
// `isOff` (the point and its pixel footprint times the hit threshold) rejects.
struct ColourPoints {
    int surface = 0, off = 0;
};
template <class IsOff>
ColourPoints settledColourPoints(const Preset& scene, IsOff isOff) {
    test::glContext();
    viewport::Viewport view;
    const viewport::Converged settled =
        viewport::renderUntilSettled(view, scene.formula, scene.camera, scene.render, scene.shading, kW, kH, 400);
    EXPECT_TRUE(settled.settled);
    const std::vector<float> points = view.readColourPoints();
    const double pixelAngle = scene.camera.pixelAngle(kH);
    ColourPoints c;
    for (size_t i = 0; i + 3 < points.size(); i += 4) {
        if (points[i + 3] == 0.0f) continue;
        const vec3 q(points[i], points[i + 1], points[i + 2]);
        ++c.surface;
        c.off += isOff(q, pixelAngle * length(q - scene.camera.position) * scene.render.detail);
    }
    return c;
}

TEST(OvershootRecovery, TheViewportsHitsLieOnTheSurface) {
    const Preset ball = solidBall();
    const auto [surface, off] = settledColourPoints(ball, [&](const vec3& q, double threshold) {
        const double footprint = threshold / ball.render.detail * std::max(ball.render.detail, 1.0);
        return std::abs(length(q) - kBallRadius) > 2.0 * footprint;
    });
    std::printf("viewport: %d of %d colour points off the ball's surface\n", off, surface);
    EXPECT_GT(surface, kW * kH / 2);
    EXPECT_LE(off, surface / 20);
}

// HitRule::InsideOnly (Mandelbulber2's iteration_threshold_mode): rays stop only where the
// point is inside, the crossing bisected to within the hit threshold, never where the estimate
// falls under it. The squaring ball at a threshold of 6 footprints: the plain march stops where
// the potential estimate (half the distance) falls under it, about 12 footprints out; with hits
// only inside every renderer stops within one threshold outside the ball's surface. The hit
// pixels are the ball's, less at most a few rim rays whose chord is shorter than a step.
struct BallHits {
    int ballPixels = 0, hits = 0, missed = 0, strayHits = 0;
    int withinThreshold = 0;  // hits whose depth lies in [exact - threshold, exact]
};

// The direction of pixel (x, y)'s centre ray.
vec3 pixelRay(const Preset& p, int x, int y) {
    return p.camera.rayDirection(2.0 * (x + 0.5) / kW - 1.0, 1.0 - 2.0 * (y + 0.5) / kH, double(kW) / kH);
}

BallHits ballHits(const Preset& p, const std::vector<float>& depth) {
    BallHits b;
    const double pixelAngle = p.camera.pixelAngle(kH);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const vec3 rd = pixelRay(p, x, y);
            const vec3 ro = p.camera.position;
            const double half = dot(ro, rd), h = half * half - (dot(ro, ro) - kBallRadius * kBallRadius);
            const bool ball = h > 0.0;
            const double exact = ball ? -half - std::sqrt(h) : 0.0;
            const float t = depth[size_t(y) * kW + size_t(x)];
            const bool hit = t < kMiss;
            b.ballPixels += ball;
            b.hits += hit;
            if (ball && !hit) ++b.missed;
            if (!ball && hit) ++b.strayHits;
            if (ball && hit) {
                const double threshold = pixelAngle * exact * p.render.detail;
                if (t >= exact - 1.02 * threshold && t <= exact + 1e-4) ++b.withinThreshold;
            }
        }
    return b;
}

TEST(HitInsideOnly, RaysStopOnTheBoundedOrbitsSurfaceNotWhereTheEstimateIsSmall) {
    Preset p = solidBall();
    p.formula.deFactor = 1.0;
    p.render.detail = 6.0;
    for (const Renderer& r : kRenderers) {
        const BallHits plain = ballHits(p, r.depth(p));
        Preset inside = p;
        inside.formula.hitRule = HitRule::InsideOnly;
        const BallHits b = ballHits(inside, r.depth(inside));
        std::printf(
            "%s: %d ball pixels; plain march %d of %d hits within a threshold of the surface; hits only "
            "inside %d of %d (%d missed, %d stray)\n",
            r.name, b.ballPixels, plain.withinThreshold, plain.hits, b.withinThreshold, b.hits, b.missed, b.strayHits);
        ASSERT_GT(b.ballPixels, kW * kH / 2);
        // The plain march stops far out (316 of 3072 hits within a threshold, 184 beside the ball).
        EXPECT_LT(plain.withinThreshold, plain.hits / 5) << r.name;
        EXPECT_GT(plain.strayHits, b.ballPixels / 50) << r.name;
        EXPECT_EQ(b.strayHits, 0) << r.name;
        EXPECT_LE(b.missed, b.ballPixels / 50) << r.name;
        EXPECT_EQ(b.withinThreshold, b.hits) << r.name;
    }
}

// The viewport's settled colour points with hits only inside lie within a threshold outside the
// ball's surface (the refinement toward the estimate's level set is skipped in this mode).
TEST(HitInsideOnly, TheViewportsHitsLieOnTheBoundedOrbitsSurface) {
    Preset p = solidBall();
    p.formula.deFactor = 1.0;
    p.formula.hitRule = HitRule::InsideOnly;
    p.render.detail = 6.0;
    const auto [surface, off] = settledColourPoints(p, [](const vec3& q, double threshold) {
        return length(q) - kBallRadius > 1.05 * threshold || length(q) < kBallRadius - 1e-4;
    });
    std::printf("viewport, hits only inside: %d of %d colour points off the ball's surface\n", off, surface);
    EXPECT_GT(surface, kW * kH / 2);
    EXPECT_EQ(off, 0);
}

// Formula::hitRule InteriorWalls (Mandelbulber2's interior mode): the squaring ball cut open by an
// intersected plane that keeps z <= 0, the cut facing the camera. With the plain rule a ray
// through the cut stops on it; with interior walls it crawls through the set and stops where it
// comes out, in the hit band outside the far hemisphere: between 1 and 2 thresholds out, the
// ball's potential estimate being half the distance (at most 3 allowed for the crawl's last step).
// The rays counted are those that cross the plane well inside the ball.
struct CutBallHits {
    int throughCut = 0, onCut = 0, onFarWall = 0;
};

CutBallHits cutBallHits(const Preset& p, const std::vector<float>& depth) {
    CutBallHits c;
    const double pixelAngle = p.camera.pixelAngle(kH);
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const vec3 rd = pixelRay(p, x, y);
            const vec3 ro = p.camera.position;
            const double tCut = -ro.z / rd.z;
            if (!(tCut > 0.0) || length(ro + rd * tCut) > 0.9 * kBallRadius) continue;
            ++c.throughCut;
            const double half = dot(ro, rd), h = half * half - (dot(ro, ro) - kBallRadius * kBallRadius);
            const double tOut = -half + std::sqrt(h);
            const double t = depth[size_t(y) * kW + size_t(x)];
            if (std::abs(t - tCut) <= pixelAngle * tCut * p.render.detail) ++c.onCut;
            const double threshold = pixelAngle * tOut * p.render.detail;
            if (t >= tOut && t <= tOut + 3.0 * threshold) ++c.onFarWall;
        }
    return c;
}

Preset cutBall() {
    Preset p = solidBall();
    p.formula.deFactor = 1.0;
    SceneObject cut = SceneObject::make(*findObject("plane"));
    cut.operation = ObjectOperation::Intersect;
    p.formula.objects.push_back(cut);
    return p;
}

TEST(InteriorWalls, ACutOpenSetShowsTheWallWhereRaysComeOut) {
    Preset plain = cutBall();
    Preset walls = plain;
    walls.formula.hitRule = HitRule::InteriorWalls;
    for (const Renderer& r : kRenderers) {
        const CutBallHits before = cutBallHits(plain, r.depth(plain));
        const CutBallHits after = cutBallHits(walls, r.depth(walls));
        std::printf(
            "%s: %d rays through the cut; plain rule %d on the cut; interior walls %d on the far wall, %d on "
            "the cut\n",
            r.name, after.throughCut, before.onCut, after.onFarWall, after.onCut);
        ASSERT_GT(after.throughCut, kW * kH / 4) << r.name;
        EXPECT_EQ(before.onCut, before.throughCut) << r.name;
        EXPECT_EQ(after.onFarWall, after.throughCut) << r.name;
        EXPECT_EQ(after.onCut, 0) << r.name;
    }
}

// The viewport marches the same rule a step per pass: at rest its colour points lie on the far
// wall (or its rim, within a threshold above the plane), none on the cut.
TEST(InteriorWalls, TheViewportsColourPointsLieOnTheWallsNotTheCut) {
    Preset p = cutBall();
    p.formula.hitRule = HitRule::InteriorWalls;
    const auto [surface, off] = settledColourPoints(p, [](const vec3& q, double threshold) {
        const bool onSphere = length(q) >= kBallRadius - 1e-4 && length(q) <= kBallRadius + 3.0 * threshold;
        return !onSphere || q.z > threshold;
    });
    std::printf("viewport, interior walls: %d of %d colour points off the far wall\n", off, surface);
    EXPECT_GT(surface, kW * kH / 4);
    EXPECT_EQ(off, 0);
}

}  // namespace
}  // namespace fraktal
