// Fitting a formula's settings to its blocks and framing its object from the DE
// (app/editor/formula_fit.hpp).
#include <gtest/gtest.h>

#include <filesystem>

#include "app/editor/formula_edits.hpp"
#include "app/editor/formula_fit.hpp"
#include "core/preset.hpp"

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
    EXPECT_GE(box.bailout, 100.0);
    Formula ifs = templateWith({"sierpinski_fold", "scale"});
    EXPECT_TRUE(fitEstimatorToBlocks(ifs));
    EXPECT_EQ(ifs.estimator.block->membership, Membership::Distance);
    EXPECT_GE(ifs.bailout, 1000.0);
    // A formula that already fits is left alone, a user's distance estimator included.
    Formula bulb = shippedFormula("mandelbulb.json");
    EXPECT_FALSE(fitEstimatorToBlocks(bulb));
    Formula menger = shippedFormula("menger.json");
    EXPECT_FALSE(fitEstimatorToBlocks(menger));
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

}  // namespace
}  // namespace fraktal::editor
