// Fragmentarium frags as fraktal presets (core/import/frag_import, core/whole_de): the DE with
// its helpers becomes a whole-DE estimator, the uniforms its parameters, the chosen #preset's
// values and camera apply, what fraktal cannot draw is refused with the reason, and the render
// of a frag whose DE fraktal's own blocks also build matches theirs.
#include "core/import/frag_import.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "app/editor/document/formula_edits.hpp"
#include "core/gl/de_probe.hpp"
#include "core/glsl_gen.hpp"
#include "core/render/still_job.hpp"
#include "core/render/still_renderer.hpp"
#include "core/scene/scene_import.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

std::filesystem::path fragPath(const std::string& name) { return test::sourceDir() / "tests/data/frag_import" / name; }

ImportedScene importFrag(const std::string& name, SceneImportOptions options = {}) {
    return importSceneFile(fragPath(name), options);
}

// The reason importing `name` is refused with (empty when it imports).
std::string refusal(const std::string& name) {
    try {
        importFrag(name);
        return "";
    } catch (const PresetError& e) {
        return e.what();
    }
}

const CustomBlock::Definition::Param* param(const Formula& f, const std::string& name) {
    for (const auto& p : f.customBlocks.at(0)->definition().params)
        if (p.name == name) return &p;
    return nullptr;
}

vec3 value(const Formula& f, const std::string& name) {
    const auto& params = f.estimator.block->params;
    for (size_t i = 0; i < params.size(); ++i)
        if (params[i].name == name) return f.estimator.values.at(i);
    ADD_FAILURE() << "no parameter " << name;
    return vec3(0.0);
}

std::vector<bool> hitMask(const Preset& preset, const RenderSettings& r) {
    test::glContext();
    gl::StillRenderer renderer(preset.formula, 128);
    renderer.setScene(preset.formula, preset.camera, r, resolveShading(preset.shading, r, preset.formula), 0.0);
    ImageStrip image;
    image.resize(r.width, 0, r.height);
    for (const TileRect& tile : tilesOf({0, 0, r.width, r.height}, 128)) renderer.renderTile(tile, image);
    std::vector<bool> mask(size_t(r.width) * size_t(r.height));
    for (size_t i = 0; i < mask.size(); ++i) mask[i] = image.rgba[4 * i + 3] > 0.5f;
    return mask;
}

double intersectionOverUnion(const std::vector<bool>& a, const std::vector<bool>& b) {
    size_t both = 0, either = 0;
    for (size_t i = 0; i < a.size(); ++i) {
        both += a[i] && b[i];
        either += a[i] || b[i];
    }
    return either ? double(both) / double(either) : 1.0;
}

}  // namespace

TEST(FragImport, DEBecomesAWholeDEEstimatorAlone) {
    const Preset p = importFrag("menger.frag").preset;
    const Formula& f = p.formula;
    EXPECT_TRUE(f.nodes.empty());
    ASSERT_TRUE(f.estimator.block->wholeDE);
    EXPECT_TRUE(f.estimator.block->custom);
    const std::string glsl(f.estimator.block->glsl);
    // The helpers the DE calls come along; MathUtils' rotation is fraktal's own; the raytracer's
    // main() and uniforms stay behind.
    EXPECT_NE(glsl.find("void sortDescending(inout vec3 z)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("mat3 rotationMatrix3(vec3 v, float angle)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("vec4 orbitTrap"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("uniform"), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("rotationMatrixXYZ"), std::string::npos) << "functions the DE never calls are left out";
    // An int uniform is a float parameter read as int, a checkbox a toggle read as a test.
    EXPECT_NE(glsl.find("n < int(Iterations)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("if ((Twist > 0.5))"), std::string::npos) << glsl;
}

TEST(FragImport, UniformsBecomeParametersWithRangesDefaultsTooltipsAndGroups) {
    const Formula f = importFrag("annotations.frag").preset.formula;
    ASSERT_EQ(f.estimator.block->params.size(), 7u);

    const auto* radius = param(f, "Radius");
    ASSERT_TRUE(radius);
    EXPECT_EQ(radius->type, ParamType::Float);
    EXPECT_EQ(radius->min, 0.1);
    EXPECT_EQ(radius->max, 3.0);
    EXPECT_EQ(radius->defaultValue.x, 1.0);
    EXPECT_EQ(radius->help, "Radius of the sphere");
    EXPECT_EQ(radius->group, "Shape");
    EXPECT_EQ(value(f, "Radius").x, 1.2) << "the Default preset's value";

    const auto* ripples = param(f, "Ripples");
    ASSERT_TRUE(ripples);
    EXPECT_EQ(ripples->type, ParamType::Float);
    EXPECT_EQ(ripples->max, 12.0);
    EXPECT_EQ(value(f, "Ripples").x, 5.0);

    const auto* center = param(f, "Center");
    ASSERT_TRUE(center);
    EXPECT_EQ(center->type, ParamType::Vec3);
    EXPECT_EQ(center->defaultValue, vec3(0.0, 0.25, 0.0));
    EXPECT_EQ(center->min, -1.0);

    const auto* stretch = param(f, "Stretch");
    ASSERT_TRUE(stretch);
    EXPECT_EQ(stretch->type, ParamType::Vec3);
    EXPECT_EQ(stretch->min, 0.5);
    EXPECT_EQ(stretch->defaultValue, vec3(1.0, 1.0, 0.5)) << "z unused, kept in range";

    const auto* hollow = param(f, "Hollow");
    ASSERT_TRUE(hollow);
    EXPECT_EQ(hollow->type, ParamType::Toggle);
    EXPECT_EQ(hollow->defaultValue.x, 1.0);
    EXPECT_EQ(hollow->group, "Finish");
    EXPECT_EQ(value(f, "Hollow").x, 0.0) << "the preset unchecks it";

    const auto* tint = param(f, "Tint");
    ASSERT_TRUE(tint);
    EXPECT_EQ(tint->type, ParamType::Vec3);
    EXPECT_EQ(tint->defaultValue, vec3(0.8, 0.6, 0.4));
    EXPECT_EQ(tint->max, 1.0);

    const auto* profile = param(f, "Profile");
    ASSERT_TRUE(profile);
    EXPECT_EQ(profile->max, 2.0);
    EXPECT_NE(profile->help.find("0: Flat, 1: Sine, 2: Square"), std::string::npos) << profile->help;
    EXPECT_EQ(value(f, "Profile").x, 2.0);

    const std::string glsl(f.estimator.block->glsl);
    EXPECT_NE(glsl.find("#define RADIUS_SCALE 1.0"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("p.xy /= Stretch.xy"), std::string::npos) << glsl;
}

TEST(FragImport, PresetAndCameraFollowTheFragsModel) {
    const Preset p = importFrag("menger.frag").preset;
    EXPECT_NE(p.description.find("preset Default"), std::string::npos) << p.description;
    EXPECT_EQ(p.camera.position, vec3(2.3, 1.7, 3.0));
    EXPECT_EQ(p.camera.target, vec3(0.0));
    EXPECT_NEAR(p.camera.fovY, 45.0, 1e-6) << "FOV is tan(fovY / 2)";
    EXPECT_NEAR(p.render.detail, 0.5, 0.01) << "Detail's cone in pixel footprints at 720 rows";
    EXPECT_EQ(p.formula.deFactor, 1.0);
    EXPECT_GE(p.render.maxSteps, 200);
    EXPECT_EQ(value(p.formula, "Iterations").x, 8.0);

    SceneImportOptions twisted;
    twisted.fragPreset = "Twisted";
    const Preset t = importFrag("menger.frag", twisted).preset;
    EXPECT_EQ(t.camera.position, vec3(0.0, 0.0, 5.0));
    EXPECT_NEAR(t.camera.fovY, 2.0 * std::atan(0.6) * 180.0 / M_PI, 1e-9);
    EXPECT_EQ(value(t.formula, "Twist").x, 1.0);
    EXPECT_EQ(value(t.formula, "Angle").x, 30.0) << "a locked preset value is a value";
    EXPECT_EQ(value(t.formula, "Iterations").x, 5.0);

    SceneImportOptions missing;
    missing.fragPreset = "Nowhere";
    try {
        importFrag("menger.frag", missing);
        FAIL() << "an unknown preset name imports";
    } catch (const PresetError& e) {
        EXPECT_NE(std::string(e.what()).find("Nowhere"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("Default, Twisted"), std::string::npos) << e.what();
    }
}

// The presets the editor offers: every #preset of the frag once, in file order, and the one the
// import applied (FragM's choice by default, else the one asked for).
TEST(FragImport, ListsThePresetsItCanApply) {
    const ImportedScene byDefault = importFrag("menger.frag", {.measure = false});
    EXPECT_EQ(byDefault.presetChoices, (std::vector<std::string>{"Default", "Twisted"}));
    EXPECT_EQ(byDefault.presetUsed, "Default");
    const ImportedScene twisted = importFrag("menger.frag", {.measure = false, .fragPreset = "Twisted"});
    EXPECT_EQ(twisted.presetChoices, byDefault.presetChoices);
    EXPECT_EQ(twisted.presetUsed, "Twisted");
    EXPECT_EQ(twisted.preset.camera.position, vec3(0.0, 0.0, 5.0));
    // FragM applies the first preset, in sorted order, named like "default".
    const ImportedScene sorted =
        importSceneFile(test::sourceDir() / "tests/data/frag/box_fold.frag", {.lenient = true, .measure = false});
    EXPECT_EQ(sorted.presetChoices, (std::vector<std::string>{"Default", "A default of sorts"}));
    EXPECT_EQ(sorted.presetUsed, "A default of sorts");
}

TEST(FragImport, PresetRoundTripsExactly) {
    for (const char* name : {"menger.frag", "annotations.frag", "init_bulb.frag"}) {
        const Preset p = importFrag(name).preset;
        const std::string saved = serializePreset(p);
        const Preset again = parsePreset(saved, "saved.json");
        EXPECT_EQ(serializePreset(again), saved) << name;
        EXPECT_EQ(customBlockToJson(*again.formula.customBlocks.at(0)),
                  customBlockToJson(*p.formula.customBlocks.at(0)))
            << name;
        EXPECT_EQ(again.formula.estimator.values, p.formula.estimator.values) << name;
        EXPECT_EQ(again.camera, p.camera) << name;
        EXPECT_EQ(again.formula.structureKey(), p.formula.structureKey()) << name;
    }
}

// The editor's node-list edits leave an imported frag's formula as a preset can hold it: no block
// is added before its whole DE (the loader refuses one), and a whole DE replaces the estimator of
// an empty node list only. Every edit tried leaves a document that saves and loads back equal.
TEST(FragImport, NodeListEditsKeepAWholeDEFormulaLoadable) {
    Preset p = importFrag("menger.frag").preset;
    ASSERT_TRUE(editor::wholeDEFormula(p.formula));
    const BlockDesc& wholeDE = *p.formula.estimator.block;
    int refused = 0;
    for (const BlockDesc& block : allBlocks()) {
        if (block.isEstimator()) continue;
        EXPECT_FALSE(editor::addNode(p, block)) << block.id << " was added before a whole DE";
        ++refused;
    }
    EXPECT_GT(refused, 50);
    EXPECT_TRUE(p.formula.nodes.empty());
    const Preset back = parsePreset(serializePreset(p), "edited.json");
    EXPECT_EQ(serializePreset(back), serializePreset(p));

    Preset bulb = test::shippedPreset("mandelbulb.json");
    ASSERT_FALSE(bulb.formula.nodes.empty());
    EXPECT_FALSE(editor::setEstimator(bulb.formula, wholeDE)) << "a whole DE closed a node list";
    EXPECT_FALSE(editor::wholeDEFormula(bulb.formula));
    Formula empty = bulb.formula;
    empty.nodes.clear();
    EXPECT_TRUE(editor::setEstimator(empty, wholeDE));
    EXPECT_TRUE(editor::wholeDEFormula(empty));
}

TEST(FragImport, RefusesWhatFraktalCannotDrawNamingTheReason) {
    EXPECT_NE(refusal("refuse_texture.frag").find("a texture is sampled inside the DE"), std::string::npos)
        << refusal("refuse_texture.frag");
    EXPECT_NE(refusal("refuse_inside.frag").find("Brute-Raytracer frag"), std::string::npos)
        << refusal("refuse_inside.frag");
    EXPECT_NE(refusal("refuse_buffer.frag").find("#buffer RGBA32F"), std::string::npos)
        << refusal("refuse_buffer.frag");
    EXPECT_NE(refusal("refuse_no_de.frag").find("has no function `float DE(vec3)`"), std::string::npos)
        << refusal("refuse_no_de.frag");
    for (const char* name : {"refuse_texture.frag", "refuse_inside.frag", "refuse_buffer.frag", "refuse_no_de.frag"})
        EXPECT_NE(refusal(name).find(name), std::string::npos) << "the message names the file: " << refusal(name);
    // Lenient: the #buffer pass is dropped and listed in the description.
    const Preset buffer = importFrag("refuse_buffer.frag", {.lenient = true}).preset;
    EXPECT_NE(buffer.description.find("#buffer"), std::string::npos) << buffer.description;
    // No DE, a texture in the DE: nothing to write even when lenient.
    EXPECT_THROW(importFrag("refuse_texture.frag", {.lenient = true}), PresetError);
    EXPECT_THROW(importFrag("refuse_no_de.frag", {.lenient = true}), PresetError);
}

TEST(FragImport, InitAndOrbitTrapReachTheShader) {
    const Preset p = importFrag("init_bulb.frag").preset;
    const std::string code = generateFormulaGLSL(p.formula).code;
    // init() runs before each DE call, after the orbit trap is reset; the trap is the fractal's.
    const size_t reset = code.find("fraktalDE_orbitTrap = vec4(10000.0);");
    const size_t init = code.find("fraktalDE_init();");
    const size_t call = code.find("return fraktalDE_DE(p.xyz);");
    ASSERT_NE(reset, std::string::npos) << code;
    ASSERT_NE(init, std::string::npos) << code;
    ASSERT_NE(call, std::string::npos) << code;
    EXPECT_LT(reset, init);
    EXPECT_LT(init, call);
    EXPECT_NE(code.find("trap = vec4(fraktalDE_orbitTrap.xyz, sqrt(max(fraktalDE_orbitTrap.w, 0.0)));"),
              std::string::npos);
    // The frag's uniforms are fraktal's estimator uniforms; its names cannot meet fraktal's.
    EXPECT_NE(code.find("uniform float u_est_Power;"), std::string::npos);
    EXPECT_NE(code.find("fraktalDE_rot = fraktalDE_rotationMatrixXYZ(u_est_Turn);"), std::string::npos) << code;

    test::glContext();
    gl::DEProbe probe(p.formula);
    const std::vector<vec3> points = {vec3(0.0, 0.0, 2.0), vec3(0.3, 0.2, 0.1), vec3(1.2, 0.0, 0.0)};
    const auto samples = probe.evaluate(p.formula, points);
    ASSERT_EQ(samples.size(), points.size());
    EXPECT_GT(samples[0].distance, 0.2f) << "outside the bulb, under a unit away";
    EXPECT_LT(samples[0].distance, 1.5f);
    EXPECT_LT(samples[1].distance, 0.0f + 1e-3f) << "inside the bulb";
    // The orbit trap the DE lowered: finite, and under FragM's start of 10000.
    EXPECT_LT(samples[2].trap.x, 10.0f);
}

TEST(FragImport, ValueEditOfAFragParameterDoesNotRecompile) {
    const Preset p = importFrag("annotations.frag").preset;
    Formula edited = p.formula;
    edited.estimator.values.at(0).x = 0.6;  // Radius
    EXPECT_EQ(edited.structureKey(), p.formula.structureKey());
    EXPECT_EQ(generateFormulaGLSL(edited).code, generateFormulaGLSL(p.formula).code);

    test::glContext();
    gl::DEProbe probe(p.formula);  // one program for both values
    const std::vector<vec3> points = {vec3(3.0, 1.25, 0.0), vec3(0.5, 0.25, 2.0)};
    const auto before = probe.evaluate(p.formula, points);
    const auto after = probe.evaluate(edited, points);
    const auto fresh = gl::DEProbe(edited).evaluate(edited, points);
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_NEAR(after[i].distance - before[i].distance, 0.6f, 1e-3f) << "the radius shrank by 0.6";
        EXPECT_EQ(after[i].distance, fresh[i].distance) << "the uniform, not a recompile, carries the value";
    }
}

// The frag's Menger sponge is the one presets/menger.json builds from blocks: the same hit mask.
TEST(FragImport, RenderMatchesTheBuiltInMenger) {
    const Preset builtIn = test::shippedPreset("menger.json");
    Preset imported = importFrag("menger.frag").preset;
    EXPECT_NEAR(length(imported.camera.position - builtIn.camera.position), 0.0, 1e-12);
    EXPECT_NEAR(imported.camera.fovY, builtIn.camera.fovY, 1e-6);
    RenderSettings r = builtIn.render;
    r.width = 96;
    r.height = 64;
    r.spp = 1;
    imported.camera = builtIn.camera;
    const std::vector<bool> a = hitMask(builtIn, r);
    const std::vector<bool> b = hitMask(imported, r);
    size_t hits = 0;
    for (bool h : a) hits += h;
    EXPECT_GT(hits, a.size() / 10) << "the sponge is in view";
    const double iou = intersectionOverUnion(a, b);
    std::printf("menger.frag against presets/menger.json: IoU %.4f\n", iou);
    EXPECT_GE(iou, 0.97);
}

// fraktal's MathUtils.frag and Complex.frag keep FragM's meaning, read back from the GPU: the
// rotations turn by -angle (degrees), translate and scale4 compose as matrices, complex
// products and quotients, PI. One program serves every probe (Probe is a uniform).
TEST(FragImport, BuiltInIncludesKeepFragMsConventions) {
    Preset p = importFrag("math_utils.frag").preset;
    const std::string glsl(p.formula.estimator.block->glsl);
    EXPECT_EQ(glsl.find("cSqr"), std::string::npos) << "helpers the DE does not call stay out";
    test::glContext();
    gl::DEProbe probe(p.formula);
    const double expected[] = {-1.0, -1.0, -1.0, 5.0, -1.0, -2.0, M_PI};
    for (int k = 0; k < 7; ++k) {
        p.formula.estimator.values.at(0).x = k;
        const auto samples = probe.evaluate(p.formula, std::vector<vec3>{vec3(0.5)});
        EXPECT_NEAR(samples.at(0).distance, expected[k] * p.formula.deFactor, 1e-5) << "probe " << k;
    }
}

// The command line: `fraktal import FILE.frag` writes a preset that loads, names the whole DE,
// takes --preset and --include-dir, refuses with the reason and a non-zero exit (nothing
// written) unless --lenient; `fraktal render` opens a .frag directly.
TEST(FragImport, CommandLine) {
    const test::Sandbox box("fraktal_frag_import_");
    const std::string menger = fragPath("menger.frag").string();
    const auto imported = test::runCli("import '" + menger + "' --preset Twisted -o '" + box.path("m.json") + "'");
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    EXPECT_NE(imported.output.find("whole DE 'frag_menger' (5 parameters"), std::string::npos) << imported.output;
    const Preset p = loadPreset(box.path("m.json"));
    EXPECT_EQ(p.camera.position, vec3(0.0, 0.0, 5.0)) << "the Twisted preset's eye";

    // An include that is not built in resolves from --include-dir; without it the error names it.
    const std::string includer = box.write("uses_include.frag",
                                           "#include \"MyShapes.frag\"\n"
                                           "#include \"DE-Raytracer.frag\"\n"
                                           "float DE(vec3 p) { return ball(p); }\n");
    std::filesystem::create_directories(box.dir / "lib");
    box.write("lib/MyShapes.frag", "#donotrun\nfloat ball(vec3 p) { return length(p) - 1.0; }\n");
    const auto missing = test::runCli("import '" + includer + "' -o '" + box.path("i.json") + "'");
    EXPECT_NE(missing.exitCode, 0);
    EXPECT_NE(missing.output.find("MyShapes.frag"), std::string::npos) << missing.output;
    const auto found = test::runCli("import '" + includer + "' --include-dir '" + box.path("lib") + "' -o '" +
                                    box.path("i.json") + "'");
    EXPECT_EQ(found.exitCode, 0) << found.output;

    const std::string unmappable = fragPath("unmappable.frag").string();
    const auto refused = test::runCli("import '" + unmappable + "' -o '" + box.path("t.json") + "'");
    EXPECT_NE(refused.exitCode, 0);
    EXPECT_NE(refused.output.find("uniform Tint4"), std::string::npos) << refused.output;
    EXPECT_FALSE(std::filesystem::exists(box.path("t.json"))) << "nothing written";
    const auto lenient = test::runCli("import --lenient '" + unmappable + "' -o '" + box.path("t.json") + "'");
    EXPECT_EQ(lenient.exitCode, 0) << lenient.output;
    EXPECT_NE(lenient.output.find("dropped: uniform Tint4"), std::string::npos) << lenient.output;

    const auto render = test::runCli("render '" + menger + "' -o '" + box.path("m.exr") + "' --size 32x24 --spp 1 -q");
    EXPECT_EQ(render.exitCode, 0) << render.output;
    EXPECT_TRUE(std::filesystem::exists(box.path("m.exr")));
}

// `fraktal import` measures a frag's safe step on the GPU (its DE has no CPU twin), as the check
// does: the preset holds the measured factor, tagged for its structure, in place of FudgeFactor,
// and `fraktal check` on the written preset finds it safe on the check's own rays.
TEST(FragImport, CommandLineMeasuresTheStepFactorOnTheGpu) {
    const test::Sandbox box("fraktal_frag_measure_");
    for (const char* name : {"menger.frag", "init_bulb.frag", "annotations.frag"}) {
        SCOPED_TRACE(name);
        const std::string out = box.path(std::string(name) + ".json");
        const auto imported = test::runCli("import '" + fragPath(name).string() + "' -o '" + out + "'");
        ASSERT_EQ(imported.exitCode, 0) << imported.output;
        const Preset p = loadPreset(out);
        EXPECT_TRUE(stepFactorMeasured(p.formula)) << "the factor is not tagged as measured for the structure";
        const Preset unmeasured = importFrag(name).preset;  // no GL sampler: the frag's FudgeFactor
        EXPECT_FALSE(stepFactorMeasured(unmeasured.formula));
        const auto checked = test::runCli("check '" + out + "'");
        EXPECT_EQ(checked.exitCode, 0) << checked.output;
        // The bound is fitted to the object on the GPU: smaller than the view's framing sphere.
        EXPECT_LT(p.formula.boundRadius, unmeasured.formula.boundRadius);
        // FragM's hit test and fraktal's both compare the scaled estimate: the threshold follows the
        // factor, so the surface drawn stays where FragM draws it.
        EXPECT_NEAR(p.render.detail / p.formula.deFactor, unmeasured.render.detail / unmeasured.formula.deFactor,
                    1e-4 * unmeasured.render.detail / unmeasured.formula.deFactor)
            << "threshold " << p.render.detail << " at factor " << p.formula.deFactor;
        if (std::string(name) == "menger.frag") {  // the sponge fills the cube [-1, 1]^3
            EXPECT_TRUE(p.formula.boundRadius >= std::sqrt(3.0) && p.formula.boundRadius < 1.35 * std::sqrt(3.0))
                << p.formula.boundRadius;
        }
        std::printf("%s: measured step factor %.3f (FudgeFactor %.3f), bound %.3f (framing %.3f)\n", name,
                    p.formula.deFactor, unmeasured.formula.deFactor, p.formula.boundRadius,
                    unmeasured.formula.boundRadius);
    }
}

// A uniform of a kind fraktal's parameters lack (a colour with an intensity, read by the DE as a
// shape) is named and refuses the file; lenient, it keeps its value as a constant in the DE: the
// colour and the intensity, as FragM sets the vec4.
TEST(FragImport, UnmappableUniformIsNamedAndKeptAsAConstantWhenLenient) {
    const std::string why = refusal("unmappable.frag");
    EXPECT_NE(why.find("uniform Tint4: a floatcolor of type vec4 has no fraktal parameter"), std::string::npos) << why;
    const Preset p = importFrag("unmappable.frag", {.lenient = true}).preset;
    EXPECT_TRUE(p.formula.estimator.block->params.empty());
    EXPECT_NE(std::string(p.formula.estimator.block->glsl).find("length(p - (vec4(1.0, 0.25, 0.0, 0.5)).xyz)"),
              std::string::npos)
        << p.formula.estimator.block->glsl;
    EXPECT_NE(p.description.find("Tint4"), std::string::npos) << p.description;
}

// A vec4 slider (a quaternion's constant, a 4D offset) becomes two parameters, its xyz and its w,
// joined again where the DE reads it: the file imports strictly, with the preset's values.
TEST(FragImport, Vec4SliderBecomesAVec3AndAFloat) {
    const Preset p = importFrag("vec4_slider.frag").preset;
    const auto* xyz = param(p.formula, "Offset4");
    const auto* w = param(p.formula, "Offset4_w");
    ASSERT_TRUE(xyz && w);
    EXPECT_EQ(xyz->type, ParamType::Vec3);
    EXPECT_EQ(w->type, ParamType::Float);
    EXPECT_EQ(xyz->min, -1.0);
    EXPECT_EQ(w->max, 1.0);
    EXPECT_EQ(value(p.formula, "Offset4"), vec3(0.25, 0.0, 0.0));
    EXPECT_EQ(value(p.formula, "Offset4_w").x, 0.6);
    EXPECT_NE(std::string(p.formula.estimator.block->glsl).find("vec4(p, 0.0) - vec4(Offset4, Offset4_w)"),
              std::string::npos)
        << p.formula.estimator.block->glsl;
}

// 3D.frag's camera read by the DE (a tessellation keyed to the eye) keeps the imported camera's
// value, so the still is FragM's; the file imports strictly and says what differs.
TEST(FragImport, CameraReadByTheDEKeepsTheImportedCamera) {
    const ImportedScene s = importFrag("camera_in_de.frag");
    const std::string glsl(s.preset.formula.estimator.block->glsl);
    EXPECT_NE(glsl.find("normalize((vec3(1.5, 0.5, 3.5)))"), std::string::npos) << glsl;
    EXPECT_EQ(s.preset.camera.position, vec3(1.5, 0.5, 3.5));
    const bool named = std::any_of(s.approximated.begin(), s.approximated.end(),
                                   [](const std::string& a) { return a.find("uniform Eye") != std::string::npos; });
    EXPECT_TRUE(named) << "the approximation is not named";
}

// A preset without a camera line sees the frag from 3D.frag's default camera: Eye (0, 0, -10).
TEST(FragImport, NoCameraLineIs3DFragsDefaultCamera) {
    const Preset p = importFrag("default_camera.frag").preset;
    EXPECT_EQ(p.camera.position, vec3(0.0, 0.0, -10.0));
    EXPECT_EQ(p.camera.target, vec3(0.0));
    EXPECT_NEAR(p.camera.fovY, 2.0 * std::atan(0.4) * 180.0 / M_PI, 1e-9);
}

// DE-Raytracer's floor (EnableFloor) is a plane object: its frame's z is the floor's normal, turned
// to hold the camera on its empty side (FragM's floor is met from either side), and the bound
// reaches as far as FragM marches to it.
TEST(FragImport, FloorBecomesAPlaneObjectFacingTheCamera) {
    const vec3 n = normalize(vec3(-0.08, 1.0, 0.03));
    for (const char* presetName : {"Default", "Below"}) {
        SCOPED_TRACE(presetName);
        SceneImportOptions options;
        options.fragPreset = presetName;
        const Preset p = importFrag("floor.frag", options).preset;
        ASSERT_EQ(p.formula.objects.size(), 1u);
        const SceneObject& floor = p.formula.objects[0];
        EXPECT_EQ(floor.block, findObject("plane"));
        // Solid below z = 0 of its frame: the camera's side is the frame's +z.
        const vec3 up = std::string(presetName) == "Default" ? n : -n;
        EXPECT_LT(length(vec3(floor.localFromWorld() * up) - vec3(0.0, 0.0, 1.0)), 1e-9);
        EXPECT_NEAR(dot(floor.center, n), -0.7, 1e-9) << "the plane passes at FloorHeight";
        EXPECT_GT(dot(p.camera.position - floor.center, up), 0.0);
        EXPECT_GE(p.formula.boundRadius, 1000.0) << "FragM marches to the floor as far as MaxDistance";
    }
    EXPECT_TRUE(importFrag("menger.frag").preset.formula.objects.empty()) << "no floor where the preset has none";
}

// FragM's clock read by the DE is a parameter of its own, 0 as on FragM's first frame: the file
// imports strictly, the still is FragM's, and the parameter can be keyed to play the animation.
TEST(FragImport, TimeIsAParameterAtFragMsFirstFrame) {
    const ImportedScene s = importFrag("time.frag");
    const auto* time = param(s.preset.formula, "time");
    ASSERT_TRUE(time);
    EXPECT_EQ(time->type, ParamType::Float);
    EXPECT_EQ(time->defaultValue.x, 0.0);
    EXPECT_EQ(value(s.preset.formula, "time").x, 0.0);
    EXPECT_NE(std::string(s.preset.formula.estimator.block->glsl).find("sin(time)"), std::string::npos);
    const bool named = std::any_of(s.approximated.begin(), s.approximated.end(),
                                   [](const std::string& a) { return a.find("uniform time") != std::string::npos; });
    EXPECT_TRUE(named) << "the approximation is not named";
}

// A frag saved as Latin-1 (as many artists' editors save them) is read as Latin-1: its tooltip
// reaches the preset as UTF-8, and the preset is written (JSON holds UTF-8 alone).
TEST(FragImport, Latin1FragImportsAsUtf8) {
    const Preset p = importFrag("latin1.frag").preset;
    const auto* radius = param(p.formula, "Rayon");
    ASSERT_TRUE(radius);
    EXPECT_EQ(radius->help, "Rayon de la sph\xC3\xA8re, en unit\xC3\xA9s");
    const test::Sandbox box("fraktal_frag_latin1_");
    const auto imported =
        test::runCli("import '" + fragPath("latin1.frag").string() + "' -o '" + box.path("l.json") + "'");
    EXPECT_EQ(imported.exitCode, 0) << imported.output;
    EXPECT_EQ(loadPreset(box.path("l.json")).formula.estimator.block->params.size(), 1u);
}
