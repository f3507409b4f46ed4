// 2D fractals on the CPU: membership against geometry known in closed form (seed 2.1), the
// shipped 2D presets, and the 2D preset format.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/plane/plane_preset.hpp"
#include "core/random_vec.hpp"
#include "tests/test_support.hpp"

namespace fraktal {
namespace {

PlanePreset shippedPlanePreset(const std::string& name) {
    return loadPlanePreset(test::sourceDir() / "presets/2d" / name);
}

const double kSqrt3 = std::sqrt(3.0);

// Sierpinski: the hole removed at depth d (d = 1: the middle triangle) has its centroid at
// sum_{i=1}^{d-1} v_{a_i} / 2^i for corner choices a_i (each corner step maps z -> 2z - v).
TEST(PlaneSierpinski, PointsInRemovedTrianglesAreOutsideFromTheirDepthOn) {
    PlanePreset p = shippedPlanePreset("sierpinski_triangle.json");
    const real2 v[3] = {real2(0.0, 1.0), real2(-kSqrt3 / 2, -0.5), real2(kSqrt3 / 2, -0.5)};
    std::mt19937 rng(7);
    for (int depth = 1; depth <= 9; ++depth) {
        for (int trial = 0; trial < 20; ++trial) {
            real2 hole(0.0);
            for (int i = 1; i < depth; ++i) hole += v[rng() % 3] / std::pow(2.0, i);
            // Anywhere inside the hole, not only its centroid: the hole has circumradius 2^-d.
            const double angle = std::uniform_real_distribution<double>(0, 2 * std::numbers::pi)(rng);
            const real2 q = hole + 0.4 * std::pow(0.5, depth) * real2(std::cos(angle), std::sin(angle));
            p.formula.iterations = depth - 1;
            EXPECT_TRUE(evaluatePlane(p.formula, q).inside) << "depth " << depth << " hole, one step early";
            p.formula.iterations = depth;
            const PlaneEvaluation e = evaluatePlane(p.formula, q);
            EXPECT_FALSE(e.inside) << "depth " << depth << " at (" << q.x << ", " << q.y << ")";
            EXPECT_EQ(e.iterations, depth);
            EXPECT_GT(e.distance, 0.0);
            p.formula.iterations = 20;
            EXPECT_FALSE(evaluatePlane(p.formula, q).inside);
        }
    }
    // The vertices belong to the fractal at every depth; points outside the triangle to none.
    // (A point 1e-3 from a vertex drifts away from it by 2x per step: still in at depth 8.)
    p.formula.iterations = 8;
    for (const real2& vertex : v) EXPECT_TRUE(evaluatePlane(p.formula, vertex * 0.999).inside);
    EXPECT_FALSE(evaluatePlane(p.formula, real2(0.0, -0.51)).inside);
    EXPECT_FALSE(evaluatePlane(p.formula, real2(0.0, 1.01)).inside);
}

// Fraction of a box's area inside, by stratified jittered sampling (n x n cells).
double areaInside(const PlaneFormula& f, real2 lo, real2 hi, int n, uint32_t seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    long inside = 0;
    const real2 cell = (hi - lo) / double(n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const vec2 jitter = randomVec2(u, rng);
            inside += evaluatePlane(f, lo + cell * real2(i + jitter.x, j + jitter.y)).inside;
        }
    return double(inside) / (double(n) * n) * (hi.x - lo.x) * (hi.y - lo.y);
}

TEST(PlaneSierpinski, AreaAtDepthNIsThreeQuartersToTheN) {
    PlanePreset p = shippedPlanePreset("sierpinski_triangle.json");
    const double triangle = 3.0 * kSqrt3 / 4.0;  // circumradius 1
    for (int n : {0, 2, 4}) {
        p.formula.iterations = n;
        const double area = areaInside(p.formula, real2(-0.9, -0.55), real2(0.9, 1.05), 500, 3);
        EXPECT_NEAR(area / (triangle * std::pow(0.75, n)), 1.0, 0.01) << "depth " << n;
    }
}

// Koch: the polygon after n bump levels has area A0 (1 + 1/3 sum_{k<n} (4/9)^k) (3 bumps of area
// A0/9 first, then 4 times as many each 1/9 the size), which converges to 8/5 A0.
TEST(PlaneKoch, AreaMatchesClosedFormAtEachDepthAndConvergesToEightFifths) {
    PlanePreset p = shippedPlanePreset("koch_snowflake.json");
    const double a0 = 3.0 * kSqrt3 / 4.0;
    double closedForm = a0;
    for (int n = 0; n <= 7; ++n) {
        p.formula.iterations = n;
        if (n == 0 || n == 1 || n == 3 || n == 7) {
            const double area = areaInside(p.formula, real2(-1.2, -1.2), real2(1.2, 1.2), 600, 11);
            EXPECT_NEAR(area / closedForm, 1.0, 0.005) << "depth " << n;
            if (n == 7) {
                EXPECT_NEAR(area / a0, 8.0 / 5.0, 0.01);
            }
        }
        closedForm += a0 / 3.0 * std::pow(4.0 / 9.0, n);
    }
    EXPECT_NEAR(closedForm / a0, 8.0 / 5.0, 0.01);
    // Points of the starting triangle and of the first bumps are in; beyond the hull, out.
    p.formula.iterations = 6;
    EXPECT_TRUE(evaluatePlane(p.formula, real2(0.0, 0.0)).inside);
    EXPECT_TRUE(evaluatePlane(p.formula, real2(0.0, -0.5 - 0.25)).inside);   // bump below the bottom side
    EXPECT_FALSE(evaluatePlane(p.formula, real2(0.0, -0.5 - 0.55)).inside);  // beyond the bump's apex
    EXPECT_FALSE(evaluatePlane(p.formula, real2(1.2, 1.2)).inside);
}

PlaneFormula mandelbrot(int iterations, double bailout) {
    PlaneFormula f = shippedPlanePreset("mandelbrot.json").formula;
    f.iterations = iterations;
    f.bailout = bailout;
    return f;
}

TEST(PlaneMandelbrot, KnownPointsClassify) {
    const PlaneFormula f = mandelbrot(1000, 2.0);
    EXPECT_TRUE(evaluatePlane(f, real2(-1.0, 0.0)).inside);
    EXPECT_TRUE(evaluatePlane(f, real2(0.0, 1.0)).inside);
    EXPECT_TRUE(evaluatePlane(f, real2(0.25, 0.0)).inside);
    EXPECT_FALSE(evaluatePlane(f, real2(0.26, 0.0)).inside);
    EXPECT_FALSE(evaluatePlane(f, real2(-2.1, 0.0)).inside);
    // The distance estimate is asymptotic in |z|: it needs the preset's large bailout. -2 is in
    // the set, so at -2.1 the estimate must not exceed 0.1.
    const PlaneEvaluation out = evaluatePlane(mandelbrot(1000, 256.0), real2(-2.1, 0.0));
    EXPECT_LT(out.iterations, 8);
    EXPECT_GT(out.distance, 0.0);
    EXPECT_LE(out.distance, 0.1);
}

TEST(PlaneMandelbrot, MainCardioidAndPeriodTwoBulbInteriorsAreInside) {
    const PlaneFormula f = mandelbrot(1000, 2.0);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < 300; ++i) {
        // Main cardioid: c = mu/2 - mu^2/4 for |mu| < 1 (attracting fixed point).
        const double t = 2 * std::numbers::pi * u(rng), r = 0.97 * std::sqrt(u(rng));
        const real2 mu(r * std::cos(t), r * std::sin(t));
        const real2 cardioid = mu / 2.0 - real2(mu.x * mu.x - mu.y * mu.y, 2 * mu.x * mu.y) / 4.0;
        EXPECT_TRUE(evaluatePlane(f, cardioid).inside) << cardioid.x << " " << cardioid.y;
        // Period-2 bulb: |c + 1| < 1/4.
        const real2 bulb = real2(-1.0, 0.0) + 0.24 * std::sqrt(u(rng)) * real2(std::cos(t), std::sin(t));
        EXPECT_TRUE(evaluatePlane(f, bulb).inside) << bulb.x << " " << bulb.y;
    }
}

// The area of the Mandelbrot set is about 1.50659 (Förstemann 2012, pixel counting with error
// bounds 1.5065918849 +- 2.8e-11 by later work). Stratified sampling of the upper half (the set is
// symmetric about the real axis) with 1000 iterations lands within 1%.
TEST(PlaneMandelbrot, AreaWithinOnePercentOfPublishedValue) {
    const PlaneFormula f = mandelbrot(1000, 2.0);
    const real2 lo(-2.0, 0.0), hi(0.5, 1.25);
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int nx = 640, ny = 320;
    long inside = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const vec2 jitter = randomVec2(u, rng);
            const real2 c = lo + (hi - lo) * real2((i + jitter.x) / nx, (j + jitter.y) / ny);
            inside += evaluatePlane(f, c).inside;
        }
    const double area = 2.0 * double(inside) / (double(nx) * ny) * (hi.x - lo.x) * (hi.y - lo.y);
    EXPECT_NEAR(area, 1.50659, 0.01 * 1.50659);
}

TEST(PlaneMandelbrot, JuliaModeUsesTheFixedC) {
    PlaneFormula f = shippedPlanePreset("julia.json").formula;
    f.iterations = 500;
    const int power = f.nodes[0].block->paramIndex("julia_x");
    ASSERT_GE(power, 0);
    // c = 0: the Julia set is the unit circle, so |z0| < 1 is in and |z0| > 1 is out.
    f.nodes[0].values[size_t(power)].x = 0.0;
    f.nodes[0].values[size_t(power) + 1].x = 0.0;
    EXPECT_TRUE(evaluatePlane(f, real2(0.6, 0.7)).inside);
    EXPECT_FALSE(evaluatePlane(f, real2(0.75, 0.7)).inside);
}

TEST(PlaneMandelbrot, MultibrotPowerThreeIsSymmetricUnderThirdTurns) {
    // The Multibrot set of power d has (d - 1)-fold rotational symmetry; for d = 3, half turns:
    // c is in exactly when -c is (the orbit of -c is minus the orbit of c).
    const PlaneFormula f = shippedPlanePreset("multibrot.json").formula;
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> u(-1.3, 1.3);
    int agree = 0, insideCount = 0;
    for (int i = 0; i < 400; ++i) {
        const real2 c = randomVec2(u, rng);
        const bool a = evaluatePlane(f, c).inside, b = evaluatePlane(f, -c).inside;
        agree += a == b;
        insideCount += a;
    }
    EXPECT_EQ(agree, 400);
    EXPECT_GT(insideCount, 40);
    EXPECT_TRUE(evaluatePlane(f, real2(0.0, 0.0)).inside);
    EXPECT_FALSE(evaluatePlane(f, real2(1.0, 0.0)).inside);  // 1 -> 2 -> 9: escapes
}

TEST(PlaneSmoothIterations, ContinuousAcrossTheBailout) {
    // An orbit just past the bailout B at step n has the same smooth count as one that lands
    // exactly on B^p at step n + 1 (p = 2): n - log2(log(B^2) / log B) = n - 1.
    EXPECT_NEAR(planeSmoothIterations(10, 256.0 * 256.0, 256.0, 2.0), 9.0, 1e-12);
    EXPECT_NEAR(planeSmoothIterations(10, 256.0, 256.0, 2.0), 10.0, 1e-12);
}

TEST(PlanePreset, ShippedPresetsParseAndRoundTrip) {
    int count = 0;
    for (const auto& e : std::filesystem::directory_iterator(test::sourceDir() / "presets/2d")) {
        if (e.path().extension() != ".json") continue;
        ++count;
        ASSERT_TRUE(isPlanePresetFile(e.path())) << e.path();
        const PlanePreset p = loadPlanePreset(e.path());
        const PlanePreset back = parsePlanePreset(serializePlanePreset(p), "round trip");
        EXPECT_EQ(serializePlanePreset(back), serializePlanePreset(p)) << e.path();
        EXPECT_EQ(back.formula.structureKey(), p.formula.structureKey());
    }
    EXPECT_GE(count, 5);
    // 3D presets are not 2D ones.
    for (const auto& path : test::shippedPresets()) EXPECT_FALSE(isPlanePresetFile(path)) << path;
}

TEST(PlanePreset, BadInputNamesFieldAndReason) {
    auto error = [](const std::string& text) {
        try {
            parsePlanePreset(text, "bad.json");
        } catch (const PresetError& e) {
            return e.field() + ": " + e.reason();
        }
        return std::string("no error");
    };
    const std::string head = R"({"format": "fraktal-preset", "version": 1, "dimension": 2, )";
    EXPECT_EQ(error(head + R"("formula": {"nodes": [{"block": "mandelbulb"}]}})")
                  .find("formula.nodes[0].block: unknown 2D block 'mandelbulb' (known 2D blocks: line_fold,"),
              0u);
    EXPECT_EQ(
        error(head + R"("formula": {"nodes": [{"block": "power"}]}})"),
        "formula.nodes[0]: the node list must end with a 2D estimator (escape, triangle, segment), found 'power'");
    EXPECT_EQ(
        error(head + R"("formula": {"nodes": [{"block": "power", "params": {"power": 99}}, {"block": "escape"}]}})"),
        "formula.nodes[0].params.power: block 1 'power': value 99 is outside the range [1, 16]");
    EXPECT_EQ(error(head + R"("formula": {"nodes": [{"block": "escape"}]}, "view": {"width": -1}})"),
              "view.width: value -1 is outside the range [1e-300, 10000]");
    EXPECT_EQ(error(head + R"("formula": {"nodes": [{"block": "escape"}]}, "camera": {}})"), "camera: unknown field");
    EXPECT_EQ(error(R"({"format": "fraktal-preset", "version": 1, "dimension": 3, "formula": {}})"),
              "dimension: expected 2 for a 2D preset");
    EXPECT_NE(error("{").find("invalid JSON"), std::string::npos);
}

}  // namespace
}  // namespace fraktal
