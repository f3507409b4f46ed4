// Custom GLSL blocks: parsed from a preset, compiled into the formula like built-in blocks,
// evaluated through the GL context, with compile errors that name the block and its line.
#include <gtest/gtest.h>

#include <fstream>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/input/fly_speed.hpp"
#include "core/gl/de_probe.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

// The Mandelbox with its box fold replaced by the same fold written as a user would.
std::string mandelboxWithCustomFold(const std::string& glsl) {
    nlohmann::json j = presetToJson(loadPreset(test::sourceDir() / "presets/mandelbox.json"));
    j["formula"]["customBlocks"] = nlohmann::json::array({{
        {"id", "my_box_fold"},
        {"category", "fold"},
        {"help", "The box fold, by hand."},
        {"params", {{{"name", "fold_limit"}, {"default", 1.0}, {"min", 0.0}, {"max", 4.0}, {"help", "L"}}}},
        {"glsl", glsl},
    }});
    j["formula"]["nodes"][0] = {{"block", "my_box_fold"}, {"params", {{"fold_limit", 1.0}}}};
    return j.dump(2);
}

const char* kBoxFoldGlsl = "p.xyz = clamp(p.xyz, -fold_limit, fold_limit) * 2.0 - p.xyz;\n";

std::filesystem::path writeTemp(const std::string& name, const std::string& text) {
    const auto path = std::filesystem::temp_directory_path() / name;
    std::ofstream(path) << text;
    return path;
}

}  // namespace

TEST(CustomBlock, EvaluatesOnTheGpuLikeTheBuiltInItCopies) {
    const Preset custom = parsePreset(mandelboxWithCustomFold(kBoxFoldGlsl), "custom.json");
    const Preset builtIn = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    EXPECT_FALSE(custom.formula.cpuEvaluable());
    EXPECT_THROW(evaluate(custom.formula, vec3(0.1)), std::logic_error);

    test::glContext();
    gl::GpuSampler sampler(custom.formula);
    const auto points = test::randomPoints(4096, 6.0, 31);
    std::vector<Evaluation> gpu(points.size());
    sampler.evaluate(points, gpu);
    size_t agree = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const Evaluation cpu = evaluate(builtIn.formula, points[i]);
        agree += std::abs(gpu[i].distance - cpu.distance) <= 1e-4 * std::max(std::abs(cpu.distance), 0.1) &&
                 gpu[i].inside == cpu.inside;
    }
    EXPECT_GE(agree, points.size() * 999 / 1000);
}

// The editor's fly speed for a formula with custom GLSL (no CPU body) comes from the GL probe:
// the same distances as the built-in twin's CPU DE, and fly steps that never cross the surface.
TEST(CustomBlock, FlySpeedUsesTheGpuDistance) {
    const Preset custom = parsePreset(mandelboxWithCustomFold(kBoxFoldGlsl), "custom.json");
    const Preset builtIn = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    test::glContext();
    editor::EyeDistance eye;
    const DistanceAt gpu = eye.of(custom.formula);
    EXPECT_TRUE(eye.onGpu());
    const DistanceAt cpu = cpuDistance(builtIn.formula);
    for (const vec3& p : test::randomPoints(64, 2.0 * custom.formula.boundRadius, 7)) {
        const double expected = editor::safeDistance(builtIn.formula, cpu, p);
        EXPECT_NEAR(editor::safeDistance(custom.formula, gpu, p), expected, 1e-4 * std::max(std::abs(expected), 0.1));
    }
    // Diving straight at the surface from outside: every step stays short of it.
    vec3 position(0.0, 0.0, 2.0 * custom.formula.boundRadius);
    for (int frame = 0; frame < 16; ++frame) {  // 16 halvings: still far above float resolution
        const double before = editor::safeDistance(builtIn.formula, cpu, position);
        const vec3 step = editor::flyStep(custom.formula, gpu, position, vec3(0, 0, -1), /*dt=*/1.0, /*boost=*/4.0);
        EXPECT_LE(length(step), 0.5 * before * (1.0 + 1e-3) + 1e-6);
        position += step;
        ASSERT_GT(editor::safeDistance(builtIn.formula, cpu, position), 0.0) << "frame " << frame;
    }
    // The fly speed is not the bound-sphere fallback (which is 0 inside the sphere).
    EXPECT_LT(length(position), custom.formula.boundRadius);
    // A structure that does not compile falls back to the bound sphere instead of throwing.
    Preset broken = parsePreset(mandelboxWithCustomFold("p.xyz = undefined_function(p.xyz);\n"), "broken.json");
    const DistanceAt fallback = eye.of(broken.formula);
    EXPECT_FALSE(eye.onGpu());
    EXPECT_EQ(fallback(vec3(0.0)), 0.0);
    EXPECT_NEAR(fallback(vec3(0.0, 0.0, broken.formula.boundRadius + 1.0)), 1.0, 1e-12);
}

// Editing a custom block's GLSL keeps its id but must recompile: it is a change of structure.
TEST(CustomBlock, EditingItsGlslIsAStructureChange) {
    const Preset a = parsePreset(mandelboxWithCustomFold(kBoxFoldGlsl), "a.json");
    const Preset b = parsePreset(
        mandelboxWithCustomFold("p.xyz = clamp(p.xyz, -fold_limit, fold_limit) * 2.0 - p.xyz;\n// edited\n"), "b.json");
    const Preset again = parsePreset(mandelboxWithCustomFold(kBoxFoldGlsl), "again.json");
    EXPECT_NE(a.formula.structureKey(), b.formula.structureKey());
    EXPECT_EQ(a.formula.structureKey(), again.formula.structureKey());
}

// A transform block with one float parameter "amount" (default 0.5, range 0..2), as the GLSL
// block editor would build it.
CustomBlock::Definition amountTransform(const std::string& id, const std::string& amountHelp, const std::string& glsl) {
    CustomBlock::Definition d;
    d.id = id;
    d.category = Category::Transform;
    d.help = "test";
    d.params.push_back({"amount", amountHelp, ParamType::Float, vec3(0.5), 0.0, 2.0});
    d.glsl = glsl;
    return d;
}

// The editor's GLSL block editor applies a definition through upsertCustomBlock: a new block is
// added, an edited one replaces the old everywhere it is used (values kept where the parameter
// survives, clamped to its new range), and an unsound one is refused with the reason.
TEST(CustomBlock, EditorAddsAndReplacesBlocksInTheFormula) {
    Formula f = loadPreset(test::sourceDir() / "presets/mandelbox.json").formula;
    const Formula original = f;
    const CustomBlock::Definition d = amountTransform("wobble", "how much", "p.x += amount * sin(p.y);\n");

    CustomBlock::Definition builtInId = d;
    builtInId.id = "box_fold";
    EXPECT_NE(editor::upsertCustomBlock(f, builtInId).find("built-in"), std::string::npos);
    CustomBlock::Definition looping = d;
    looping.glsl = "for (int i = 0; i < 9; ++i) p.x += 1.0;\n";
    EXPECT_NE(editor::upsertCustomBlock(f, looping), "");
    EXPECT_EQ(f.structureKey(), original.structureKey()) << "a refused definition changed the formula";
    EXPECT_TRUE(f.customBlocks.empty());

    ASSERT_EQ(editor::upsertCustomBlock(f, d), "");
    ASSERT_EQ(f.customBlocks.size(), 1u);
    const auto custom = editor::customBlocksIn(f, Category::Transform);
    ASSERT_EQ(custom.size(), 1u);
    ASSERT_TRUE(editor::addNode(f, *custom[0], 1));
    f.nodes[1].values[0] = vec3(1.5);
    std::weak_ptr<const CustomBlock> first = f.customBlocks[0];
    const std::string keyBefore = f.structureKey();

    // Edit: a narrower range for "amount", a new parameter, new GLSL.
    CustomBlock::Definition edited = d;
    edited.params[0].max = 1.0;
    edited.params.push_back({"phase", "", ParamType::Float, vec3(0.25), -1.0, 1.0});
    edited.glsl = "p.x += amount * sin(p.y + phase);\n";
    ASSERT_EQ(editor::upsertCustomBlock(f, edited), "");
    EXPECT_EQ(f.customBlocks.size(), 1u);
    EXPECT_TRUE(first.expired()) << "the old definition is still referenced";
    EXPECT_EQ(f.nodes[1].block, &f.customBlocks[0]->desc());
    EXPECT_EQ(f.nodes[1].values[0].x, 1.0);   // kept, clamped to the new range
    EXPECT_EQ(f.nodes[1].values[1].x, 0.25);  // the new parameter's default
    EXPECT_NE(f.structureKey(), keyBefore);

    // The block in use as a node cannot become an estimator.
    CustomBlock::Definition estimator = edited;
    estimator.category = Category::Estimator;
    estimator.glsl = "return length(p.xyz) / p.w;\n";
    EXPECT_NE(editor::upsertCustomBlock(f, estimator).find("category"), std::string::npos);
    EXPECT_EQ(f.nodes[1].block->category, Category::Transform);

    // What the editor built saves into a preset and loads back as the same formula.
    Preset p = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    p.formula = f;
    const Preset back = parsePreset(serializePreset(p), "back.json");
    EXPECT_EQ(back.formula.structureKey(), f.structureKey());
    EXPECT_EQ(back.formula.nodes[1].values[0].x, 1.0);
}

// A parameter's type is part of the generated GLSL (float or vec3 uniform): changing it alone
// must recompile too.
TEST(CustomBlock, ChangingAParameterTypeIsAStructureChange) {
    Formula f = loadPreset(test::sourceDir() / "presets/mandelbox.json").formula;
    CustomBlock::Definition d = amountTransform("shift", "", "p.xyz += amount;\n");
    ASSERT_EQ(editor::upsertCustomBlock(f, d), "");
    ASSERT_TRUE(editor::addNode(f, f.customBlocks[0]->desc(), 0));
    const std::string before = f.structureKey();
    d.params[0].type = ParamType::Vec3;
    ASSERT_EQ(editor::upsertCustomBlock(f, d), "");
    EXPECT_NE(f.structureKey(), before);
}

TEST(CustomBlock, ParametersAreUniformsWithTheirDeclaration) {
    Preset p = parsePreset(mandelboxWithCustomFold(kBoxFoldGlsl), "custom.json");
    const BlockDesc& block = *p.formula.nodes[0].block;
    ASSERT_EQ(block.params.size(), 1u);
    EXPECT_EQ(block.params[0].name, "fold_limit");
    EXPECT_EQ(block.params[0].max, 4.0);
    EXPECT_EQ(block.params[0].help, "L");
    const std::string code = generateFormulaGLSL(p.formula).code;
    EXPECT_NE(code.find("uniform float u_n0_fold_limit;"), std::string::npos);
    // A value edit keeps the code; the same probe serves both values.
    Formula edited = p.formula;
    edited.nodes[0].values[0].x = 1.3;
    EXPECT_EQ(generateFormulaGLSL(edited).code, code);
}

TEST(CustomBlock, RoundTripsThroughAPresetAndALibrary) {
    const Preset p = parsePreset(mandelboxWithCustomFold(kBoxFoldGlsl), "custom.json");
    const std::string saved = serializePreset(p);
    const Preset again = parsePreset(saved, "saved.json");
    EXPECT_EQ(serializePreset(again), saved);
    ASSERT_EQ(again.formula.customBlocks.size(), 1u);
    EXPECT_EQ(again.formula.customBlocks[0]->definition().glsl, kBoxFoldGlsl);

    const auto library = writeTemp("fraktal_blocks.json", serializeBlockLibrary(p.formula.customBlocks));
    const CustomBlocks loaded = loadBlockLibrary(library.string());
    ASSERT_EQ(loaded.size(), 1u);
    EXPECT_EQ(customBlockToJson(*loaded[0]), customBlockToJson(*p.formula.customBlocks[0]));
}

TEST(CustomBlock, CompileErrorNamesTheBlockAndItsLine) {
    const auto file = writeTemp("fraktal_custom_broken.json",
                                mandelboxWithCustomFold("p.xyz = clamp(p.xyz, -fold_limit, fold_limit) * 2.0 - p.xyz;\n"
                                                        "p.xyz += not_declared_anywhere;\n"));
    const test::CliRun r = test::runCli("check --rays 4 --grid 4 " + file.string());
    EXPECT_EQ(r.exitCode, 1) << r.output;
    // Numbered from 1 with the label, as the editor's node list shows it (no label: the id).
    EXPECT_NE(r.output.find("node 1 \"my_box_fold\" (my_box_fold), GLSL line 2"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("not_declared_anywhere"), std::string::npos) << r.output;
}

TEST(CustomBlock, CheckMeasuresACustomFormulaOnTheGpu) {
    const auto file = writeTemp("fraktal_custom_ok.json", mandelboxWithCustomFold(kBoxFoldGlsl));
    const test::CliRun r = test::runCli("check --rays 20 --grid 8 " + file.string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("custom blocks are evaluated there"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("conservative"), std::string::npos) << r.output;
}

// The example in presets/README.md compiles and evaluates to finite distances.
TEST(CustomBlock, TheDocumentedExampleWorks) {
    const Preset p = loadPreset(test::sourceDir() / "tests/custom_presets/twisted_mandelbulb.json");
    test::glContext();
    gl::GpuSampler sampler(p.formula);
    const auto points = test::randomPoints(1000, p.formula.boundRadius, 41);
    std::vector<Evaluation> out(points.size());
    sampler.evaluate(points, out);
    size_t finite = 0, inside = 0;
    for (const Evaluation& e : out) {
        finite += std::isfinite(e.distance);
        inside += e.inside;
    }
    EXPECT_EQ(finite, points.size());
    EXPECT_GT(inside, 10u);  // the twisted bulb is there
}

// A custom block's on/off parameter: declared as "toggle", a float uniform in GLSL, a checkbox
// in the editor, true/false in the preset's node; a toggle with another range is refused.
TEST(CustomBlock, ToggleParametersAreDeclaredOnce) {
    nlohmann::json j = nlohmann::json::parse(mandelboxWithCustomFold(kBoxFoldGlsl));
    auto& params = j["formula"]["customBlocks"][0]["params"];
    params.push_back({{"name", "mirror"}, {"type", "toggle"}, {"default", true}, {"help", "Mirror x."}});
    j["formula"]["customBlocks"][0]["glsl"] = std::string(kBoxFoldGlsl) + "if (mirror > 0.5) p.x = -p.x;\n";
    j["formula"]["nodes"][0]["params"]["mirror"] = false;
    const Preset p = parsePreset(j.dump(), "custom_toggle.json");
    const BlockDesc& block = *p.formula.nodes[0].block;
    ASSERT_EQ(block.params.size(), 2u);
    EXPECT_EQ(block.params[1].type, ParamType::Toggle);
    EXPECT_EQ(block.params[1].defaultValue, vec3(1.0, 0.0, 0.0));
    EXPECT_EQ(p.formula.nodes[0].values[1], vec3(0.0));
    EXPECT_NE(generateFormulaGLSL(p.formula).code.find("uniform float u_n0_mirror;"), std::string::npos);
    const nlohmann::json saved = presetToJson(p);
    EXPECT_EQ(saved["formula"]["customBlocks"][0]["params"][1]["type"], "toggle");
    EXPECT_EQ(saved["formula"]["customBlocks"][0]["params"][1]["default"], true);
    EXPECT_EQ(saved["formula"]["nodes"][0]["params"]["mirror"], false);
    EXPECT_EQ(serializePreset(parsePreset(saved.dump(), "again.json")), serializePreset(p));

    params[1]["max"] = 2.0;
    try {
        parsePreset(j.dump(), "bad_toggle.json");
        ADD_FAILURE() << "a toggle with range 0..2 was accepted";
    } catch (const PresetError& e) {
        EXPECT_EQ(e.field(), "formula.customBlocks[0].params[1]");
        EXPECT_NE(e.reason().find("a toggle is 0 or 1"), std::string::npos) << e.what();
    }
}
