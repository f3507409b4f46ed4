// GPU-free viewport logic: frame decisions, the AA schedule, the conservative stop (cone
// coverage), the reprojection margin, statistics and the image error. No GL context.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "core/random_vec.hpp"
#include "core/viewport/camera_path.hpp"
#include "core/viewport/frame_logic.hpp"
#include "core/viewport/image_error.hpp"

namespace fraktal::viewport {
namespace {

FrameKey baseKey() {
    FrameKey k;
    k.width = 64;
    k.height = 48;
    k.structure = "mandelbulb|add_c|escape_log";
    k.values = "1,2,3";
    k.maxSteps = 256;
    return k;
}

TEST(ViewportLogic, FirstFrameResizeAndEditsReset) {
    const FrameKey a = baseKey();
    EXPECT_EQ(decideFrame(nullptr, a, true), FrameAction::Reset);
    FrameKey b = a;
    b.width = 65;
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reset);
    b = a;
    b.values = "1,2,4";
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reset);
    b = a;
    b.shading.s.aoSteps += 1;
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reset);
    b = a;
    b.maxSteps = 128;
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reset);
    b = a;  // an edit during a camera move still resets: carried distances belong to the old fractal
    b.values = "9";
    b.camera.position.x += 0.1;
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reset);
}

TEST(ViewportLogic, CameraMoveReprojectsOnlyWhenEnabled) {
    const FrameKey a = baseKey();
    FrameKey b = a;
    b.camera.position.x += 0.01;
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reproject);
    EXPECT_EQ(decideFrame(&a, b, false), FrameAction::Reset);
}

// Dynamic resolution: a new grid size under motion reprojects (world points scatter into any
// grid); a new size with the camera still, or with an edit, resets.
TEST(ViewportLogic, ResizeDuringCameraMoveReprojects) {
    const FrameKey a = baseKey();
    FrameKey b = a;
    b.width = 32;
    b.height = 24;
    b.camera.position.x += 0.01;
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reproject);
    EXPECT_EQ(decideFrame(&a, b, false), FrameAction::Reset);
    b.values = "9";
    EXPECT_EQ(decideFrame(&a, b, true), FrameAction::Reset);
    b = a;
    b.width = 128;
    // The camera still: right after a move (the controller changing the grid in a pause) the
    // image reprojects into the new grid; at rest it restarts.
    EXPECT_EQ(decideFrame(&a, b, true, FrameAction::Reproject), FrameAction::Reproject);
    EXPECT_EQ(decideFrame(&a, b, true, FrameAction::Hold), FrameAction::Reproject);
    EXPECT_EQ(decideFrame(&a, b, false, FrameAction::Hold), FrameAction::Reset);
    EXPECT_EQ(decideFrame(&a, b, true, FrameAction::Continue), FrameAction::Reset);
    EXPECT_EQ(decideFrame(&a, b, true, FrameAction::Reset), FrameAction::Reset);
}

TEST(ViewportLogic, StillCameraContinuesButRestartsOnceAfterMotion) {
    const FrameKey a = baseKey();
    EXPECT_EQ(decideFrame(&a, a, true, FrameAction::Continue), FrameAction::Continue);
    EXPECT_EQ(decideFrame(&a, a, true, FrameAction::Reset), FrameAction::Continue);
    // The first still frame after a move holds (a pause within a drag), the second restarts.
    EXPECT_EQ(decideFrame(&a, a, true, FrameAction::Reproject), FrameAction::Hold);
    EXPECT_EQ(decideFrame(&a, a, true, FrameAction::Hold), FrameAction::Reset);
    // Moving again after a held frame reprojects from it.
    FrameKey moved = a;
    moved.camera.position.x += 0.01;
    EXPECT_EQ(decideFrame(&a, moved, true, FrameAction::Hold), FrameAction::Reproject);
}

TEST(ViewportLogic, FormulaValuesKeyChangesWithAnyValue) {
    Formula f;
    const std::string k0 = formulaValuesKey(f);
    f.bailout += 1e-9;
    EXPECT_NE(formulaValuesKey(f), k0);
}

TEST(ViewportLogic, AAJitterCentredFirstThenDistinctInsideThePixel) {
    EXPECT_EQ(aaJitter(0), glm::dvec2(0.0));
    std::set<std::pair<double, double>> seen;
    glm::dvec2 mean(0.0);
    const int n = 64;
    for (int k = 1; k <= n; ++k) {
        const glm::dvec2 j = aaJitter(k);
        EXPECT_GE(j.x, -0.5);
        EXPECT_LT(j.x, 0.5);
        EXPECT_GE(j.y, -0.5);
        EXPECT_LT(j.y, 0.5);
        EXPECT_TRUE(seen.insert({j.x, j.y}).second) << "sample " << k << " repeats";
        mean += j / double(n);
    }
    // Low discrepancy: the samples balance about the pixel centre.
    EXPECT_LT(std::abs(mean.x), 0.05);
    EXPECT_LT(std::abs(mean.y), 0.05);
}

TEST(ViewportLogic, AAScheduleRisesAtRestUpToTheCap) {
    const AASchedule s{4};
    EXPECT_EQ(s.next(0, true), 1);
    EXPECT_EQ(s.next(2, true), 3);
    EXPECT_EQ(s.next(3, true), -1);
    EXPECT_EQ(s.next(0, false), -1);
}

// A unit sphere at the origin; camera rays from (0,0,-5) along +z and slightly off axis. The
// coverage a centre ray builds by sphere tracing must stay in front of the first hit of every ray
// in its cone (the conservative stop) and still get close to the surface.
double sphereDE(const vec3& p) { return length(p) - 1.0; }

double firstHit(const vec3& ro, const vec3& rd) {  // ray-sphere intersection
    const double b = dot(ro, rd), c = dot(ro, ro) - 1.0, h = b * b - c;
    return h < 0.0 ? INFINITY : -b - std::sqrt(h);
}

TEST(ViewportLogic, ConeCoverageStaysInFrontOfEveryRayInTheCone) {
    const vec3 ro(0.0, 0.0, -5.0);
    const double tanHalf = 0.01;
    for (double offset : {0.0, 0.5, 0.9, 0.99}) {  // centre rays from the middle to the silhouette
        const vec3 rd = normalize(vec3(offset * 0.2, 0.0, 1.0));
        double t = 0.0, covered = 0.0;
        for (int i = 0; i < 200; ++i) {
            const double d = sphereDE(ro + rd * t);
            covered = extendConeCoverage(covered, t, d, tanHalf);
            if (d < 1e-6) break;
            t += d;
        }
        // Rays on the cone's rim, all around.
        for (int k = 0; k < 16; ++k) {
            const double a = 2.0 * M_PI * k / 16.0;
            const vec3 side = normalize(glm::cross(rd, vec3(0, 1, 0.1)));
            const vec3 up = glm::cross(side, rd);
            const vec3 r = normalize(rd + (side * std::cos(a) + up * std::sin(a)) * tanHalf);
            EXPECT_LE(covered, firstHit(ro, r) + 1e-9) << "offset " << offset << " direction " << k;
        }
        if (std::isfinite(firstHit(ro, rd)) && offset < 0.9) {  // not useless: near the centre ray's hit
            EXPECT_GT(covered, 0.9 * firstHit(ro, rd));
        }
    }
}

TEST(ViewportLogic, ConeCoverageNeedsOverlapAndRoom) {
    EXPECT_EQ(extendConeCoverage(1.0, 3.0, 0.5, 0.01), 1.0);    // a ball that does not reach back
    EXPECT_EQ(extendConeCoverage(1.0, 1.0, 0.005, 0.01), 1.0);  // narrower than the cone
    EXPECT_GT(extendConeCoverage(1.0, 1.0, 0.5, 0.01), 1.0);
    EXPECT_EQ(extendConeCoverage(1.0, 1.0, -0.5, 0.01), 1.0);  // inside the surface
}

TEST(ViewportLogic, ReprojectionMarginGrowsWithDistanceAndDetail) {
    EXPECT_GT(reprojectionMargin(2.0, 0.001, 0.5), reprojectionMargin(1.0, 0.001, 0.5));
    EXPECT_GT(reprojectionMargin(1.0, 0.001, 2.0), reprojectionMargin(1.0, 0.001, 1.0));
    // At least the hit threshold (detail footprints): a hit may lie that far in front of the surface.
    EXPECT_GE(reprojectionMargin(1.0, 0.001, 3.0), 0.001 * 3.0);
}

// A ray that found nothing inside the bound sphere is parked so far along that, after the camera
// moves by up to 0.4 bound radii (any direction, from inside or outside the sphere), the point
// backed off by the reprojection margin still lies past the sphere's far side from the new
// camera, whatever the new ray: the start pass then marches nothing for it. Parking one radius
// out (just past the far side) does not have this property.
TEST(ViewportLogic, ParkedRaysStayPastTheBoundSphereAfterACameraMove) {
    const double radius = 2.0, pixelAngle = 0.003, detail = 1.0;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uniform(0.0, 1.0);
    auto direction = [&] {
        vec3 v;
        do v = randomVec3(uniform, rng) * 2.0 - 1.0;
        while (length(v) < 1e-3 || length(v) > 1.0);
        return normalize(v);
    };
    auto pastFarSide = [&](const vec3& point, const vec3& camera) {
        const double t = length(point - camera);
        // Every ray's far side of the sphere lies within |camera| + radius of the camera.
        return t - reprojectionMargin(t, pixelAngle, detail) >= length(camera) + radius;
    };
    int justPastFailed = 0;
    for (int i = 0; i < 20000; ++i) {
        const vec3 camera = direction() * (5.0 * radius * uniform(rng));
        const vec3 ray = direction();
        const vec3 moved = camera + direction() * (0.4 * radius * uniform(rng));
        const vec3 parked = camera + ray * parkedDistance(length(camera), radius);
        ASSERT_TRUE(pastFarSide(parked, moved)) << "case " << i;
        if (!pastFarSide(camera + ray * (length(camera) + radius), moved)) ++justPastFailed;
    }
    EXPECT_GT(justPastFailed, 1000);
}

// Carried colours expire spread evenly over the last quarter of the carry limit, never later; so
// colours shaded in the same frame are not all shaded again in one frame.
TEST(ViewportLogic, CarriedColoursExpireSpreadOverTheLastQuarterOfTheCarryLimit) {
    for (int maxCarry : {16, 7}) {
        SCOPED_TRACE(maxCarry);
        const int earliest = maxCarry - maxCarry / 4, kinds = maxCarry - earliest + 1;
        std::vector<int> lifetimes(size_t(maxCarry) + 1, 0);
        const int pixels = 200 * 100;
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 200; ++x) {
                int age = 1;
                while (!carriedColourExpires(age, maxCarry, x, y)) ++age;
                const int kept = age - 1;  // frames the colour was kept
                ASSERT_GE(kept, earliest);
                ASSERT_LE(kept, maxCarry);
                ++lifetimes[size_t(kept)];
            }
        for (int kept = earliest; kept <= maxCarry; ++kept)
            EXPECT_NEAR(double(lifetimes[size_t(kept)]) / pixels, 1.0 / kinds, 0.2 / kinds) << "kept " << kept;
    }
    EXPECT_TRUE(carriedColourExpires(1, 0, 3, 4));  // 0: never carried
}

TEST(ViewportLogic, SummarizeDividesByPixels) {
    FrameCounters c{1000, 25, 75, 50, 10};
    const FrameStats s = summarize(c, 10, 10, FrameAction::Reproject);
    EXPECT_DOUBLE_EQ(s.deEvalsPerPixel, 10.0);
    EXPECT_DOUBLE_EQ(s.shareReprojected, 0.25);
    EXPECT_DOUBLE_EQ(s.shareRestarted, 0.75);
    EXPECT_DOUBLE_EQ(s.shareConverged, 0.5);
    EXPECT_EQ(s.action, FrameAction::Reproject);
}

TEST(ViewportLogic, DisplayPsnrInfiniteForEqualAndFallsWithError) {
    std::vector<float> a(4 * 16, 0.25f), b = a;
    EXPECT_TRUE(std::isinf(displayPsnr(a, b)));
    b[0] = 0.3f;
    const double small = displayPsnr(a, b);
    b[1] = 0.9f;
    EXPECT_LT(displayPsnr(a, b), small);
    EXPECT_THROW(displayPsnr(a, std::vector<float>(8)), std::invalid_argument);
}

TEST(ViewportLogic, CameraPathsMoveAndStartAtThePreset) {
    Camera c;
    c.position = vec3(0, 1, 4);
    for (CameraPath p : {CameraPath::Orbit, CameraPath::Dolly, CameraPath::Pan}) {
        EXPECT_EQ(cameraOnPath(c, p, 0), c);
        EXPECT_NE(cameraOnPath(c, p, 5), c);
        EXPECT_EQ(parseCameraPath(toString(p)), p);
    }
    // An orbit keeps the distance to the target.
    EXPECT_NEAR(length(cameraOnPath(c, CameraPath::Orbit, 30).position - c.target), length(c.position - c.target),
                1e-12);
    EXPECT_FALSE(parseCameraPath("spin").has_value());
}

}  // namespace
}  // namespace fraktal::viewport
