// The formula panel's edits of whole fractals combined with the first (Formula::fractals): adding
// a preset's fractal takes its own settings, nodes and placement and nothing of its scene; the
// limit; removal; which presets the "Add fractal" menu offers; and compile errors of a combined
// fractal not pinned on the first fractal's nodes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/editor/document/formula_edits.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;


// A folder of its own under the system's temporary folder, removed at the end of the test.
struct TempFolder {
    fs::path path;
    TempFolder() {
        static int made = 0;
        path = fs::temp_directory_path() /
               ("fraktal_fractals_" + std::to_string(::getpid()) + "_" + std::to_string(made++));
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempFolder() { fs::remove_all(path); }
};

TEST(EditorFractals, AddTakesThePresetsFractalAndNothingOfItsScene) {
    Formula f = test::shippedPreset("menger.json").formula;
    // A source with a scene of its own: objects and combined fractals, a bound and a hit rule.
    Formula source = test::shippedPreset("menger_carved_by_mandelbulbs.json").formula.fractals.at(1).formula;
    source.placement.center = vec3(0.5, 0.0, -0.25);
    source.placement.scale = 2.0;
    source.placement.repeat = vec3(3.0, 0.0, 0.0);
    source.boundRadius = 7.0;
    source.hitRule = HitRule::InteriorWalls;
    ASSERT_TRUE(addObject(source, *findObject("torus")));
    ASSERT_TRUE(addFractal(source, test::shippedPreset("menger.json").formula));
    const Formula before = f;

    ASSERT_TRUE(addFractal(f, source));
    ASSERT_EQ(f.fractals.size(), 1u);
    const CombinedFractal& c = f.fractals[0];
    EXPECT_EQ(c.operation, ObjectOperation::Join);
    EXPECT_TRUE(c.enabled);
    const Formula& g = c.formula;
    ASSERT_EQ(g.nodes.size(), source.nodes.size());
    for (size_t k = 0; k < g.nodes.size(); ++k) {
        EXPECT_EQ(g.nodes[k].block, source.nodes[k].block);
        EXPECT_EQ(g.nodes[k].values, source.nodes[k].values);
    }
    EXPECT_EQ(g.estimator.block, source.estimator.block);
    EXPECT_EQ(g.iterations, source.iterations);
    EXPECT_EQ(g.bailout, source.bailout);
    EXPECT_EQ(g.deFactor, source.deFactor);
    EXPECT_EQ(g.placement.center, source.placement.center);
    EXPECT_EQ(g.placement.axis, source.placement.axis);
    EXPECT_EQ(g.placement.angle, source.placement.angle);
    EXPECT_EQ(g.placement.scale, 2.0);
    EXPECT_EQ(g.placement.repeat, source.placement.repeat);
    // Its objects and fractals are not carried along; the bound and hit rule are the holder's.
    EXPECT_TRUE(g.objects.empty());
    EXPECT_TRUE(g.fractals.empty());
    EXPECT_EQ(f.boundRadius, before.boundRadius);
    EXPECT_EQ(f.hitRule, before.hitRule);
    // The first fractal is untouched, and the change is one of structure (a recompile).
    EXPECT_EQ(f.nodes.size(), before.nodes.size());
    EXPECT_TRUE(f.objects.empty());
    EXPECT_NE(f.structureKey(), before.structureKey());

    // The document round-trips through the preset format with the fractal in it.
    Preset p = test::shippedPreset("menger.json");
    p.formula = f;
    const Preset again = parsePreset(serializePreset(p), "round trip");
    ASSERT_EQ(again.formula.fractals.size(), 1u);
    EXPECT_EQ(again.formula.structureKey(), f.structureKey());
    EXPECT_EQ(again.formula.fractals[0].formula.placement.scale, 2.0);
}

TEST(EditorFractals, AddStopsAtTheLimitAndRemoveTakesTheOneAsked) {
    Formula f = test::shippedPreset("menger.json").formula;
    const Formula bulb = test::shippedPreset("mandelbulb.json").formula;
    const Formula box = test::shippedPreset("mandelbox.json").formula;
    for (int k = 0; k < kMaxCombinedFractals; ++k) EXPECT_TRUE(addFractal(f, k % 2 ? box : bulb)) << k;
    EXPECT_FALSE(addFractal(f, bulb));
    EXPECT_EQ(int(f.fractals.size()), kMaxCombinedFractals);

    EXPECT_FALSE(removeFractal(f, -1));
    EXPECT_FALSE(removeFractal(f, kMaxCombinedFractals));
    EXPECT_TRUE(removeFractal(f, 0));  // the bulb: the box moves up
    EXPECT_EQ(int(f.fractals.size()), kMaxCombinedFractals - 1);
    EXPECT_EQ(f.fractals[0].formula.estimator.block, box.estimator.block);
    while (!f.fractals.empty()) EXPECT_TRUE(removeFractal(f, 0));
    EXPECT_EQ(f.structureKey(), test::shippedPreset("menger.json").formula.structureKey());
}

TEST(EditorFractals, CustomBlocksAreNotCombined) {
    Formula custom = test::shippedPreset("mandelbox.json").formula;
    CustomBlock::Definition d;
    d.id = "wobble";
    d.category = Category::Transform;
    d.help = "test";
    d.glsl = "p.x += 0.1 * sin(p.y);\n";
    ASSERT_EQ(upsertCustomBlock(custom, d), "");
    // A custom block defined but unused still belongs to its formula alone.
    EXPECT_FALSE(combinable(custom));
    ASSERT_TRUE(addNode(custom, *customBlocksIn(custom, Category::Transform).at(0), 0));
    EXPECT_FALSE(combinable(custom));
    Formula f = test::shippedPreset("menger.json").formula;
    EXPECT_FALSE(addFractal(f, custom));
    EXPECT_TRUE(f.fractals.empty());
    EXPECT_TRUE(combinable(test::shippedPreset("mandelbulb.json").formula));
}

TEST(EditorFractals, MenuListsTheLoadable3DPresetsWithBuiltInBlocks) {
    TempFolder a, b;
    fs::copy_file(test::sourceDir() / "presets" / "mandelbulb.json", a.path / "mandelbulb.json");
    fs::copy_file(test::sourceDir() / "presets" / "menger.json", a.path / "b_menger.json");
    fs::copy_file(test::sourceDir() / "presets" / "2d" / "mandelbrot.json", a.path / "flat.json");  // 2D
    std::ofstream(a.path / "broken.json") << "{ not json";
    std::ofstream(a.path / "notes.txt") << "not a preset";
    Preset custom = test::shippedPreset("mandelbox.json");
    CustomBlock::Definition d;
    d.id = "wobble";
    d.category = Category::Transform;
    d.help = "test";
    d.glsl = "p.x += 0.1 * sin(p.y);\n";
    ASSERT_EQ(upsertCustomBlock(custom.formula, d), "");
    savePresetFile(a.path / "custom.json", custom);
    ASSERT_NO_THROW(loadPreset(a.path / "custom.json"));
    fs::copy_file(test::sourceDir() / "presets" / "mandelbox.json", b.path / "a_box.json");

    const std::vector<FractalChoice> choices = combinableFractals({a.path, b.path, a.path / "missing"});
    std::vector<std::string> names;
    for (const FractalChoice& c : choices) names.push_back(c.name);
    // Folder by folder, sorted within each; the missing folder adds nothing.
    EXPECT_EQ(names, (std::vector<std::string>{"b_menger", "mandelbulb", "a_box"}));
    ASSERT_EQ(choices.size(), 3u);
    EXPECT_EQ(choices[1].formula.structureKey(), test::shippedPreset("mandelbulb.json").formula.structureKey());

    // Every shipped 3D preset without custom blocks is offered, mandelbulb among them.
    const std::vector<FractalChoice> shippedChoices = combinableFractals({test::sourceDir() / "presets"});
    EXPECT_GE(shippedChoices.size(), 20u);
    EXPECT_TRUE(std::any_of(shippedChoices.begin(), shippedChoices.end(),
                            [](const FractalChoice& c) { return c.name == "mandelbulb"; }));
}

TEST(EditorFractals, CompileErrorOfACombinedFractalNamesNoNodeOfTheFirst) {
    // ShaderSource::explainLog names a combined fractal's nodes after its number (from 2).
    EXPECT_EQ(nodeNamedInLog("GLSL compile error in x:\nfractal 2: node 3 \"Box fold\" (box_fold), GLSL line 2: "
                             "error: ...",
                             5),
              -1);
    EXPECT_EQ(nodeNamedInLog("fractal 3: estimator \"Box\" (box), GLSL line 1: error", 5), -1);
    // The first fractal's own nodes and estimator are still found; the first named counts.
    EXPECT_EQ(nodeNamedInLog("node 3 \"Box fold\" (box_fold), GLSL line 2: error", 5), 2);
    EXPECT_EQ(nodeNamedInLog("estimator \"Box\" (box), GLSL line 1: error", 5), 5);
    EXPECT_EQ(nodeNamedInLog("node 1 \"Box fold\" (box_fold), GLSL line 2: error\nfractal 2: node 3 \"x\" (x)", 5), 0);
}

}  // namespace
}  // namespace fraktal::editor
