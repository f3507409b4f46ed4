// Whole fractals combined (Formula::fractals, Mandelbulber2's boolean mode): each placed, then
// joined, intersected or carved in order; the CPU evaluation against the definitions, the preset
// round trip and its errors, the GPU against the CPU.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/animation.hpp"
#include "core/gl/de_probe.hpp"
#include "core/glsl_gen.hpp"
#include "core/json_reader.hpp"
#include "core/preset.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

Formula shipped(const char* name) { return loadPreset(test::sourceDir() / "presets" / name).formula; }

// The Menger sponge with the Mandelbulb (escape-time) and a Mandelbox (escape-time) beside it,
// each placed: the three operations and a fractal switched off.
Formula spongeWithBulbs() {
    Formula f = shipped("menger.json");
    f.iterations = 3;  // a sponge solid enough that random points fall in it and in the bulbs
    CombinedFractal carve{shipped("mandelbulb.json"), ObjectOperation::Carve, true};
    carve.formula.placement.center = vec3(1.0, 1.0, 1.0);
    carve.formula.placement.scale = 0.9;
    CombinedFractal join{shipped("mandelbulb.json"), ObjectOperation::Join, true};
    join.formula.placement.axis = vec3(1.0, 0.2, 0.0);
    join.formula.placement.angle = -70.0;
    join.formula.placement.scale = 2.4;
    CombinedFractal off{shipped("menger.json"), ObjectOperation::Intersect, false};
    f.fractals = {carve, join, off};
    return f;
}

// A placed fractal is the fractal at the point taken into its frame, its estimate divided by the
// scale: the definition in core/formula.hpp, written out.
TEST(CombinedFractals, PlacementMovesRepeatsTurnsAndScalesThePoint) {
    const Formula bulb = shipped("mandelbulb.json");
    Formula placed = bulb;
    placed.placement.center = vec3(0.5, -0.25, 2.0);
    placed.placement.axis = vec3(0.0, 1.0, 1.0);
    placed.placement.angle = 35.0;
    placed.placement.scale = 1.7;
    const glm::dmat3 turn(glm::rotate(glm::dmat4(1.0), glm::radians(35.0), normalize(vec3(0.0, 1.0, 1.0))));
    for (const vec3& local : test::randomPoints(500, 2.0, 71)) {
        // The world point whose frame point is `local`.
        const vec3 world = placed.placement.center + turn * (local / 1.7);
        EXPECT_NEAR(distanceEstimate(placed, world), distanceEstimate(bulb, local) / 1.7, 1e-9);
        EXPECT_EQ(evaluate(placed, world).inside, evaluate(bulb, local).inside);
    }
    // Repeated every (3, 0, 4): the same at whole cells along x and z, not along y.
    Formula repeated = bulb;
    repeated.placement.repeat = vec3(3.0, 0.0, 4.0);
    int differ = 0;
    for (const vec3& p : test::randomPoints(500, 1.4, 72)) {
        EXPECT_NEAR(distanceEstimate(repeated, p + vec3(6.0, 0.0, -4.0)), distanceEstimate(bulb, p), 1e-9);
        differ += std::abs(distanceEstimate(repeated, p + vec3(0.0, 3.0, 0.0)) - distanceEstimate(bulb, p)) > 1e-3;
    }
    EXPECT_GT(differ, 250);
    EXPECT_EQ(repeatCell(vec3(1.6, -1.6, 7.0), vec3(3.0, 3.0, 0.0)), vec3(1.6 - 3.0, -1.6 + 3.0, 7.0));
}

// Join is the least estimate, intersect the greatest, carve the greatest of the estimate and the
// carving fractal's negated; membership combines alike; a fractal switched off counts for nothing.
// An escape-time fractal's estimate is no distance inside its set: there its carved space counts
// as 1.5 hit thresholds, so that a marched ray crawls through it.
TEST(CombinedFractals, OperationsCombineEachFractalAlone) {
    const Formula f = spongeWithBulbs();
    const double threshold = 1e-3;
    int carvedInside = 0, joinedInside = 0;
    for (const vec3& p : test::randomPoints(4000, 1.8, 73)) {
        const Evaluation sponge = evaluate(f.fractalAlone(0), p, threshold);
        const Evaluation carve = evaluate(f.fractalAlone(1), p, threshold);
        const Evaluation join = evaluate(f.fractalAlone(2), p, threshold);
        const double cut = carve.inside ? 1.5 * threshold : -carve.distance;
        const double expected = std::min(std::max(sponge.distance, cut), join.distance);
        const Evaluation both = evaluate(f, p, threshold);
        EXPECT_DOUBLE_EQ(both.distance, expected);
        EXPECT_EQ(both.inside, (sponge.inside && !carve.inside) || join.inside);
        EXPECT_EQ(both.escaped, !both.inside);
        carvedInside += sponge.inside && carve.inside;
        joinedInside += join.inside && !sponge.inside;
        // The trap of the fractal that set the distance.
        if (join.distance < std::max(sponge.distance, cut)) {
            EXPECT_EQ(both.iterations, join.iterations);
        }
    }
    // The sample reaches into each case.
    EXPECT_GT(carvedInside, 20);
    EXPECT_GT(joinedInside, 5);
    // Outside the marcher (no threshold) the carved space counts as 0, never negative.
    Formula distanceCarve = f;
    distanceCarve.fractals.resize(1);
    distanceCarve.fractals[0] = {shipped("menger.json"), ObjectOperation::Carve, true};
    distanceCarve.fractals[0].formula.placement.scale = 2.0;
    for (const vec3& p : test::randomPoints(500, 1.5, 74)) {
        // A distance estimator (the box) carves by its signed estimate.
        const double o = distanceEstimate(distanceCarve.fractalAlone(1), p);
        EXPECT_DOUBLE_EQ(distanceEstimate(distanceCarve, p), std::max(distanceEstimate(f.fractalAlone(0), p), -o));
    }
}

// Structure (what recompiles) includes each combined fractal's nodes, operation and switch, not
// its placement or parameter values.
TEST(CombinedFractals, StructureKeyFollowsOperationsNotPlacement) {
    const Formula f = spongeWithBulbs();
    Formula moved = f;
    moved.fractals[1].formula.placement.center.x += 1.0;
    moved.fractals[0].formula.nodes[0].values[0].x += 1.0;
    moved.placement.scale = 3.0;
    EXPECT_EQ(moved.structureKey(), f.structureKey());
    Formula other = f;
    other.fractals[0].operation = ObjectOperation::Intersect;
    EXPECT_NE(other.structureKey(), f.structureKey());
    other = f;
    other.fractals[2].enabled = true;
    EXPECT_NE(other.structureKey(), f.structureKey());
    other = f;
    other.fractals.pop_back();
    EXPECT_NE(other.structureKey(), f.structureKey());
}

// Saved and read back exactly; the placement written only where it is not the identity.
TEST(CombinedFractals, PresetRoundTripsExactly) {
    Preset p = loadPreset(test::sourceDir() / "presets/menger.json");
    p.formula = spongeWithBulbs();
    p.formula.placement.repeat = vec3(4.0, 0.0, 0.0);
    p.formula.objects.push_back(SceneObject::make(*findObject("sphere")));
    p.formula.objects.back().repeat = vec3(0.0, 2.5, 0.0);
    const nlohmann::json j = presetToJson(p);
    EXPECT_EQ(j["formula"]["fractals"].size(), 3u);
    EXPECT_EQ(j["formula"]["fractals"][0]["operation"], "carve");
    EXPECT_FALSE(j["formula"]["fractals"][1].contains("operation"));  // join, the default
    EXPECT_EQ(j["formula"]["fractals"][2]["enabled"], false);
    EXPECT_FALSE(j["formula"]["fractals"][2].contains("placement"));
    EXPECT_EQ(j["formula"]["placement"]["repeat"], nlohmann::json::array({4.0, 0.0, 0.0}));
    const Preset reloaded = parsePreset(serializePreset(p), "saved.json");
    EXPECT_EQ(serializePreset(reloaded), serializePreset(p));
    EXPECT_EQ(reloaded.formula.structureKey(), p.formula.structureKey());
    ASSERT_EQ(reloaded.formula.fractals.size(), 3u);
    EXPECT_EQ(reloaded.formula.fractals[1].formula.placement.angle, -70.0);
    EXPECT_EQ(reloaded.formula.objects.back().repeat, vec3(0.0, 2.5, 0.0));
    for (const vec3& q : test::randomPoints(200, 1.8, 75))
        EXPECT_EQ(distanceEstimate(reloaded.formula, q), distanceEstimate(p.formula, q));
    EXPECT_NE(describeFormula(p.formula).find("fractal 3 (join)"), std::string::npos) << describeFormula(p.formula);
}

// A combined fractal's placement and parameters are fields a track keys like any other.
TEST(CombinedFractals, TracksKeyACombinedFractalsPlacementAndParameters) {
    Preset p = loadPreset(test::sourceDir() / "presets/menger_carved_by_mandelbulbs.json");
    nlohmann::json j = presetToJson(p);
    j["animation"] = {{"lastFrame", 10},
                      {"tracks",
                       {{{"target", "formula.fractals[0].placement.scale"},
                         {"keys", {{{"frame", 0}, {"value", 0.9}}, {{"frame", 10}, {"value", 2.0}}}}},
                        {{"target", "formula.fractals[1].nodes[0].params.power"},
                         {"keys", {{{"frame", 0}, {"value", 8.0}}, {{"frame", 10}, {"value", 4.0}}}}}}}};
    const Preset animated = parsePreset(j.dump(), "animated.json");
    const Formula atMiddle = presetAtFrame(animated, 5.0).formula;
    EXPECT_NEAR(atMiddle.fractals[0].formula.placement.scale, 1.45, 1e-9);
    EXPECT_NEAR(atMiddle.fractals[1].formula.nodes[0].values[0].x, 6.0, 1e-9);
    EXPECT_EQ(presetAtFrame(animated, 10.0).formula.fractals[0].formula.placement.scale, 2.0);
}

// Bad combined fractals are refused naming the field and the reason.
TEST(CombinedFractals, BadFractalsAreRefusedByField) {
    Preset p = loadPreset(test::sourceDir() / "presets/menger.json");
    p.formula = spongeWithBulbs();
    const nlohmann::json good = presetToJson(p);
    auto refused = [](const nlohmann::json& bad, const std::string& field, const std::string& reason) {
        try {
            parsePreset(bad.dump(), "bad.json");
            ADD_FAILURE() << "accepted " << bad["formula"].dump();
        } catch (const PresetError& e) {
            EXPECT_EQ(e.file(), "bad.json");
            EXPECT_EQ(e.field(), field) << e.what();
            EXPECT_NE(e.reason().find(reason), std::string::npos) << e.what();
        }
    };
    nlohmann::json bad = good;
    bad["formula"]["fractals"][1]["operation"] = "xor";
    refused(bad, "formula.fractals[1].operation", "fractal 3: unknown operation \"xor\"");
    bad = good;
    bad["formula"]["fractals"][0]["placement"]["scale"] = 0.0;
    refused(bad, "formula.fractals[0].placement.scale", "outside the range");
    bad = good;
    bad["formula"]["fractals"][0]["placement"]["repeat"] = nlohmann::json::array({1.0, -1.0, 0.0});
    refused(bad, "formula.fractals[0].placement.repeat[1]", "outside the range");
    bad = good;
    bad["formula"]["fractals"][0]["nodes"] = nlohmann::json::array();
    refused(bad, "formula.fractals[0].nodes", "the node list is empty");
    bad = good;
    bad["formula"]["fractals"][0]["objects"] = nlohmann::json::array();
    refused(bad, "formula.fractals[0].objects", "unknown field");
    bad = good;
    for (int i = 0; i < 6; ++i) bad["formula"]["fractals"].push_back(good["formula"]["fractals"][0]);
    refused(bad, "formula.fractals", "too many combined fractals (9; at most 8)");
    bad = good;
    bad["formula"]["fractals"] = "carve";
    refused(bad, "formula.fractals", "expected an array of combined fractals");
}

// The generated GLSL (float) follows the CPU (double) for the combination, placements and the
// fractal switched off; compile errors name a combined fractal's nodes by fractal.
TEST(CombinedFractals, GpuAgreesWithCpu) {
    Formula f = spongeWithBulbs();
    f.fractals[0].formula.placement.repeat = vec3(1.5, 0.0, 0.0);
    test::glContext();
    gl::DEProbe probe(f);
    const std::vector<vec3> points = test::randomPoints(4096, 1.8, 76);
    const std::vector<gl::GpuSample> gpu = probe.evaluate(f, points);
    ASSERT_EQ(gpu.size(), points.size());
    size_t compared = 0, mismatched = 0, inside = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const Evaluation cpu = evaluate(f, points[i]);
        // Points where a float rounding of the point changes the double result (an orbit at the
        // bailout's edge) are not compared; the rest agree to 1e-4 relative.
        const double delta = 1e-6 * std::max(length(points[i]), 1.0);
        if (std::abs(distanceEstimate(f, points[i] + vec3(delta, 0.0, 0.0)) - cpu.distance) >
            0.5e-4 * std::max(std::abs(cpu.distance), 0.1))
            continue;
        ++compared;
        inside += cpu.inside;
        mismatched += std::abs(gpu[i].distance - cpu.distance) > 1e-4 * std::max(std::abs(cpu.distance), 0.1);
    }
    EXPECT_GT(compared, 3500u);
    EXPECT_GT(inside, 50u);
    EXPECT_EQ(mismatched, 0u);
    const GeneratedFormula g = generateFormulaGLSL(f);
    // The sponge's nodes and estimator, each bulb's, and the sponge switched off, named by fractal.
    EXPECT_EQ(g.nodeNames.size(), 5u + 3u + 3u + 5u);
    EXPECT_NE(std::find(g.nodeNames.begin(), g.nodeNames.end(), "fractal 2: node 1 \"Mandelbulb power\" (mandelbulb)"),
              g.nodeNames.end());
}

// `fraktal check` checks the combination (sound here) and will not write one step factor into a
// formula whose fractals each have their own: the file is left as it was.
TEST(CombinedFractals, CheckMeasuresTheCombinationAndRefusesToApplyOneFactor) {
    const std::filesystem::path shippedPreset = test::sourceDir() / "presets/menger_carved_by_mandelbulbs.json";
    const test::CliRun checked = test::runCli("check '" + shippedPreset.string() + "'");
    EXPECT_EQ(checked.exitCode, 0) << checked.output;
    EXPECT_NE(checked.output.find("fractal 2 (carve)"), std::string::npos) << checked.output;
    EXPECT_NE(checked.output.find("conservative"), std::string::npos) << checked.output;
    const test::Sandbox box("fraktal_combined_check");
    const std::filesystem::path copy = box.dir / "combined.json";
    std::filesystem::copy_file(shippedPreset, copy);
    const std::string before = readGuardedFile(copy);
    const test::CliRun applied = test::runCli("check --apply '" + copy.string() + "'");
    EXPECT_NE(applied.exitCode, 0);
    EXPECT_NE(applied.output.find("each with its own deFactor"), std::string::npos) << applied.output;
    EXPECT_EQ(readGuardedFile(copy), before);
}

}  // namespace
}  // namespace fraktal
