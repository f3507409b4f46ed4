// Fitting a formula's settings to its blocks and framing its object from the DE
// (core/scene/formula_fit.hpp).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <random>

#include "app/editor/document/formula_edits.hpp"
#include "core/preset.hpp"
#include "core/random_vec.hpp"
#include "core/scene/formula_fit.hpp"
#include "user_stacks.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

Formula shippedFormula(const char* name) { return loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / name).formula; }

// The Mandelbulb template with its nodes replaced by `ids`.
Formula templateWith(std::initializer_list<const char*> ids) {
    Formula f = shippedFormula("mandelbulb.json");
    f.nodes.clear();
    for (const char* id : ids) EXPECT_TRUE(addNode(f, *findBlock(id)));
    return f;
}

TEST(EditorFormulaFit, EstimatorAndBailoutFollowTheBlocks) {
    Formula box = templateWith({"box_fold", "sphere_fold", "scale", "add_c"});
    EXPECT_TRUE(fitEstimatorToBlocks(box));
    EXPECT_EQ(box.estimator.block->id, "escape_linear");
    EXPECT_GE(box.bailout, 20.0);
    Formula ifs = templateWith({"sierpinski_fold", "scale"});
    EXPECT_TRUE(fitEstimatorToBlocks(ifs));
    EXPECT_EQ(ifs.estimator.block->membership, Membership::Distance);
    EXPECT_GE(ifs.bailout, 1000.0);
    // A formula that already fits is left alone, a user's distance estimator included.
    Formula bulb = shippedFormula("mandelbulb.json");
    EXPECT_FALSE(fitEstimatorToBlocks(bulb));
    Formula menger = shippedFormula("menger.json");
    EXPECT_FALSE(fitEstimatorToBlocks(menger));
    Formula surf = shippedFormula("amazing_surf.json");  // its bailout 20 is kept
    EXPECT_FALSE(fitEstimatorToBlocks(surf));
}

TEST(EditorFormulaFit, BoundAndFrameComeFromTheDistanceField) {
    // No nodes and a sphere estimator of radius 1: the object is the unit sphere.
    Formula f = templateWith({});
    setEstimator(f, *findBlock("sphere"));
    const DistanceAt de = cpuDistance(f);
    const double bound = fittedBoundRadius(de, 16.0, 99.0);
    EXPECT_NEAR(bound, 1.15, 0.01);
    f.boundRadius = bound;
    Camera inside;
    inside.position = vec3(0.1, 0.0, 0.2);
    inside.target = vec3(0.0);
    const Camera framed = framedCamera(f, de, inside);
    EXPECT_LT(length(framed.target), 0.05);
    // Looking from the same side, as far as the sphere needs to fit the field of view.
    EXPECT_GT(dot(normalize(framed.position), normalize(inside.position)), 0.999);
    EXPECT_NEAR(length(framed.position), 1.0 / std::sin(glm::radians(framed.fovY) / 2) * 1.05, 0.1);
    EXPECT_GT(de(framed.position), 0.0);
    // A Mandelbox's extent is found the same way (its bound sphere is 10.5 in the preset).
    const Formula mandelbox = shippedFormula("mandelbox.json");
    const double boxBound = fittedBoundRadius(cpuDistance(mandelbox), 16.0, 99.0);
    EXPECT_GT(boxBound, 4.0);
    EXPECT_LT(boxBound, 14.0);
}

// A flat object: the Amazing Surf is a sheet about z = 0. Probes through the origin meet its rim
// only in its plane; the fitted bound must still hold every point of the sheet (found here by
// membership on a grid over the plane, not by the DE), or the marcher clips it.
TEST(EditorFormulaFit, BoundHoldsAFlatObjectsRim) {
    const Formula surf = shippedFormula("amazing_surf.json");
    double reach = 0.0;
    const int n = 200;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (double z : {-0.01, 0.0, 0.01}) {
                const vec3 p(-12.0 + 24.0 * (i + 0.5) / n, -12.0 + 24.0 * (j + 0.5) / n, z);
                if (length(p) > reach && evaluate(surf, p).inside) reach = length(p);
            }
    const double bound = fittedBoundRadius(cpuDistance(surf), 21.0, 99.0);
    std::printf("amazing_surf: the sheet reaches %.3f, the fitted bound is %.3f\n", reach, bound);
    EXPECT_GT(reach, 8.0);
    EXPECT_GE(bound, reach);
    EXPECT_LT(bound, 1.3 * reach);
}

// An object small in a wide search sphere: an imported view range (Mandelbulber2's
// view_distance_max, 50) about the power-2 sine bulb of its toolbar, whose hairs reach about 2.
// The first grid's cells (4 units wide) miss them; the bound must still hold every point a ray
// meets (found here by 2000 rays from all sides, each marched down the DE to a thousandth, not
// by the fit's probes), or the marcher clips the hairs.
TEST(EditorFormulaFit, BoundHoldsASmallObjectInAWideSearch) {
    const Formula bulb = parsePreset(R"({"format": "fraktal-preset", "version": 3,
        "camera": {"position": [0, -3, 1], "target": [0, 0, 0], "up": [0, 0, 1], "fovY": 50},
        "formula": {"iterations": 250, "bailout": 10.0,
        "nodes": [{"block": "mandelbulb_sine", "params": {"power": 2.0, "phi_offset": 90.0, "theta_offset": 90.0}},
                  {"block": "add_c"}, {"block": "escape_log"}]}})",
                                     "power-2 bulb")
                             .formula;
    const DistanceAt de = cpuDistance(bulb);
    std::mt19937 random(3);
    std::normal_distribution<double> gauss;
    auto direction = [&] { return normalize(randomVec3(gauss, random)); };
    double reach = 0.0;
    for (int ray = 0; ray < 2000; ++ray) {
        const vec3 from = direction() * 3.0, dir = normalize(direction() * 1.5 - from);
        double t = 0.0;
        for (int step = 0; step < 500 && t < 6.0; ++step) {
            const double d = de(from + dir * t);
            if (d < 1e-3) {
                reach = std::max(reach, length(from + dir * t));
                break;
            }
            t += d;
        }
    }
    const double bound = fittedBoundRadius(de, 50.0, 60.0);
    std::printf("power-2 sine bulb: rays meet it out to %.3f, the fitted bound is %.3f\n", reach, bound);
    EXPECT_GT(reach, 1.8);
    EXPECT_GE(bound, reach);
    EXPECT_LT(bound, 1.3 * reach);
}

// The fit measures the object, not the march: a structure without a safe step factor gets the
// smallest (0.001), and the next edit's bound must not depend on it (probes stepping a
// thousandth of the DE found no surface, and the bound stayed where it was).
TEST(EditorFormulaFit, BoundDoesNotDependOnTheStepFactor) {
    Preset safe = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "mandelbox.json");
    safe.formula.boundRadius = 30.0;
    Preset slow = safe;
    slow.formula.deFactor = kMinStepFactor;
    fitFormulaAfterEdit(safe);
    fitFormulaAfterEdit(slow);
    EXPECT_LT(safe.formula.boundRadius, 14.0);
    EXPECT_EQ(slow.formula.boundRadius, safe.formula.boundRadius);
    EXPECT_EQ(slow.formula.deFactor, kMinStepFactor);  // the factor itself is the check's business
}

TEST(EditorFormulaFit, EditLeavesAGoodCameraAndFramesABadOne) {
    Formula f = templateWith({"mandelbulb", "add_c"});
    Camera outside;
    outside.position = vec3(1.6, 1.3, 2.2);
    Camera before = outside;
    fitFormulaAfterEdit(f, outside);
    EXPECT_EQ(outside.position, before.position);
    Camera atOrigin;
    atOrigin.position = vec3(0.0, 0.0, 0.01);
    fitFormulaAfterEdit(f, atOrigin);
    EXPECT_GT(distanceEstimate(f, atOrigin.position), 0.01 * f.boundRadius);
    // Far away (the object a speck in view): framed, from the same direction.
    Camera far;
    far.position = vec3(16.0, 13.0, 22.0);
    const vec3 direction = normalize(far.position - far.target);
    fitFormulaAfterEdit(f, far);
    EXPECT_LT(length(far.position), 6.0);
    EXPECT_GT(dot(normalize(far.position - far.target), direction), 0.99);
}

// An object the bailout search's 2000 points through the bound miss: a twist in front of an
// octahedral KIFS (tests/user_stacks.hpp, seed 20) that fills under 1 % of its bound. At bailout
// 2, the first the search tries, it is gone, and no ray of `fraktal check` meets it; the search
// keeps where rays across the bound first meet it at the reference bailout, and takes 4.
TEST(EditorFormulaFit, TheBailoutKeepsAnObjectThePointsMiss) {
    std::mt19937_64 rng(20);
    const Preset p = test::drawnStack({"twist_y", "kifs_octahedral"}, rng);
    auto hits = [&](const Formula& f) {
        CpuSampler sampler(f);
        return sampleRays(sampler, p.camera, {120, 4000, 1}).raysHit;
    };
    Formula f = p.formula;
    ASSERT_EQ(f.bailout, 1000.0);
    const int atReference = hits(f);
    const auto start = std::chrono::steady_clock::now();
    fitEstimatorToBlocks(f);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Formula atTwo = f;
    atTwo.bailout = 2.0;
    std::printf("rays that meet the object: %d at bailout 1000, %d at 2, %d at the fitted %g (fitted in %.2f s)\n",
                atReference, hits(atTwo), hits(f), f.bailout, seconds);
    EXPECT_GT(atReference, 0);
    EXPECT_EQ(hits(atTwo), 0);
    EXPECT_EQ(f.bailout, 4.0);
    EXPECT_GE(hits(f), atReference);
}

}  // namespace
}  // namespace fraktal::editor
