// The Kleinian and pseudo-Kleinian presets: unbounded, periodic scenes seen from inside. The
// check's baseline marcher meets their sheets only because the estimators give them an inside
// (kleinian_de: the balls; pseudo_kleinian_de: the offset), and a preset's step factor must stay
// at or under what the check measures as safe.
#include <gtest/gtest.h>

#include <filesystem>

#include "app/editor/document/formula_edits.hpp"
#include "core/de_check.hpp"
#include "core/safe_step.hpp"
#include "editor_test_support.hpp"

using namespace fraktal;

namespace {

constexpr const char* kPresets[] = {"kleinian.json", "pseudo_kleinian.json"};

// Runs `fraktal check` on `p`, written to a temporary file.
test::CliRun checkPreset(const Preset& p, const std::string& name) {
    const auto file = std::filesystem::temp_directory_path() / ("fraktal_" + name + ".json");
    savePresetFile(file, p);
    const test::CliRun r = test::runCli("check --rays 40 " + file.string());
    std::filesystem::remove(file);
    std::filesystem::remove(file.string() + ".bak");
    return r;
}

}  // namespace

// Rays from the preset's own camera and across its bound, marched twice as finely as `fraktal
// check` marches and with seeds it does not use: most rays hit, DE * deFactor never exceeds the
// true distance along a ray, and the factor the check would call safe on these rays is at least
// the preset's.
TEST(KleinianPresets, CheckFindsHitsAndTheStepFactorNeverOvershoots) {
    for (const char* name : kPresets) {
        const Preset p = test::shippedPreset(name);
        EXPECT_FALSE(evaluate(p.formula, p.camera.position).inside) << name << ": the camera is inside the object";
        for (uint64_t seed : {3u, 4u}) {
            ConservativenessOptions o;
            o.rays = 120;
            o.stepsAcrossBound = 8000;
            o.seed = seed;
            const ConservativenessReport r = checkConservativeness(p.formula, p.camera, o);
            EXPECT_GE(r.raysHit, r.rays / 2) << name << " seed " << seed;
            EXPECT_GT(r.samples, 5000) << name << " seed " << seed;
            EXPECT_LE(r.worstRatio, 1.0) << name << " seed " << seed << ": DE * deFactor exceeds the true distance at ("
                                         << r.worstPoint.x << ", " << r.worstPoint.y << ", " << r.worstPoint.z << ")";
            const double safe = SafeStepOptions{}.factorFor(atUnitFactor(r, p.formula.deFactor), p.formula);
            EXPECT_GE(safe, p.formula.deFactor) << name << " seed " << seed;
            EXPECT_GT(r.medianRatio, 0.005) << name << ": the estimate vanishes away from the surface";
            std::printf(
                "%s seed %d: %d/%d rays hit, %ld samples, worst %.3f, median %.3f, safe factor %.3f (preset %.3f)\n",
                name, int(seed), r.raysHit, r.rays, r.samples, r.worstRatio, r.medianRatio, safe, p.formula.deFactor);
        }
        // The camera's own view: rays through a grid of pixels meet the object inside the bound.
        int hits = 0, rays = 0;
        for (double y = -0.9; y <= 0.9; y += 0.3)
            for (double x = -0.9; x <= 0.9; x += 0.3) {
                const vec3 dir = p.camera.rayDirection(x, y, 16.0 / 9.0);
                double t0 = 0.0, t1 = 0.0;
                ++rays;
                if (clipToBound(p.formula, p.camera.position, dir, t0, t1))
                    hits += baselineMarch(p.formula, p.camera.position, dir, t0, t1, p.formula.boundRadius / 4000).hit;
            }
        EXPECT_GE(hits, rays / 2) << name << ": the saved camera looks mostly at empty space";
    }
}

// Without the offset the pseudo-Kleinian's sheets have no inside: the baseline marcher finds no
// hit, and `fraktal check` says so and fails rather than passing an unmeasured estimate.
TEST(KleinianPresets, SheetsWithoutAnInsideFailTheCheck) {
    Preset p = test::shippedPreset("pseudo_kleinian.json");
    Node& estimator = p.formula.estimator;
    ASSERT_EQ(estimator.block->id, "pseudo_kleinian_de");
    estimator.values[size_t(estimator.block->paramIndex("offset"))].x = 0.0;
    ConservativenessOptions o;
    o.rays = 40;
    EXPECT_EQ(checkConservativeness(p.formula, p.camera, o).raysHit, 0);
    const test::CliRun r = checkPreset(p, "pseudo_kleinian_no_offset");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("PROBLEM: no ray hit the fractal"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("NOT SOUND"), std::string::npos) << r.output;
}

// The Kleinian step with wrap widths that are not its group's (1, any, 1) jumps at every wrap, and
// a box primitive after it overshoots the distance by hundreds of times near the jumps: no step
// factor a preset may hold makes that safe. The check says so and fails; the editor applies the
// smallest factor and says the structure has none.
TEST(KleinianPresets, WrapOutsideItsGroupHasNoSafeStepFactor) {
    Preset p = test::shippedPreset("kleinian.json");
    Formula& f = p.formula;
    Node step = Node::make(*findBlock("kleinian"));
    step.values[0].x = 1.92;
    step.values[1].x = -0.224;
    step.values[2] = vec3(1.13, 3.6, 2.7);
    step.values[3].x = 0.741;
    f.nodes = {step};
    f.estimator = Node::make(*findBlock("box"));
    f.iterations = 6;
    f.bailout = 1000.0;
    f.boundRadius = 3.0;
    f.deFactor = 1.0;
    p.camera = Camera{};
    p.camera.position = vec3(0.0, 0.0, 6.0);
    p.camera.target = vec3(0.0);
    p.animation = {};
    ASSERT_EQ(derivativeBound(f.nodes), DerivativeBound::None);

    const test::CliRun r = checkPreset(p, "kleinian_wrap_outside_group");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("PROBLEM: no step factor down to 0.001"), std::string::npos) << r.output;

    editor::AutoStepFactor a;
    ASSERT_TRUE(test::updateUntilMeasured(a, f, p.camera));
    EXPECT_TRUE(a.noSafeFactor) << "worst " << a.worst;
    EXPECT_EQ(f.deFactor, kMinStepFactor);
}

// A camera below the Kleinian's floor sits inside the lower half-space's ball: the check names it.
TEST(KleinianPresets, CameraInsideTheObjectFailsTheCheck) {
    Preset p = test::shippedPreset("kleinian.json");
    p.camera.position.y = -0.5;
    p.camera.target.y = -0.5;
    ASSERT_TRUE(evaluate(p.formula, p.camera.position).inside);
    const test::CliRun r = checkPreset(p, "kleinian_camera_inside");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("PROBLEM: the camera is inside the fractal"), std::string::npos) << r.output;
    // The shipped camera is not.
    const test::CliRun ok = test::runCli("check --rays 40 " + (test::sourceDir() / "presets/kleinian.json").string());
    EXPECT_EQ(ok.output.find("camera is inside"), std::string::npos) << ok.output;
}

// A bound wholly inside the object: every ray of the check starts inside, so nothing is measured;
// the check says so and fails rather than calling the empty sample conservative.
TEST(KleinianPresets, BoundWhollyInsideFailsTheCheck) {
    Preset p = test::shippedPreset("kleinian.json");
    p.formula.nodes.clear();
    p.formula.estimator = Node::make(*findBlock("sphere"));
    p.formula.estimator.values[0].x = 50.0;  // radius: the bound (6) lies within it
    const test::CliRun r = checkPreset(p, "all_inside");
    EXPECT_EQ(r.exitCode, 1) << r.output;
    EXPECT_NE(r.output.find("PROBLEM: every ray started inside the fractal"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("PROBLEM: no ray hit"), std::string::npos) << r.output;
}
