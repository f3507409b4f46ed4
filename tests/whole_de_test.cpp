// Whole-DE estimators (core/whole_de): a custom estimator whose GLSL is global-scope code with
// functions, loops and #define lines, alone in its formula, its loops bounded by a trip budget,
// its compile errors naming it; node-list custom blocks stay as strict as before.
#include "core/whole_de.hpp"

#include <gtest/gtest.h>

#include "core/gl/de_probe.hpp"
#include "core/glsl_gen.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

// A whole-DE preset around `glsl`, as a user (or an import) would write it.
std::string wholeDEPreset(const std::string& glsl, const nlohmann::json& nodesBefore = nlohmann::json::array()) {
    nlohmann::json j = presetToJson(test::shippedPreset("menger.json"));
    j["formula"]["customBlocks"] = nlohmann::json::array({{
        {"id", "my_de"},
        {"category", "estimator"},
        {"wholeDE", true},
        {"params", {{{"name", "Radius"}, {"default", 1.0}, {"min", 0.0}, {"max", 2.0}}}},
        {"glsl", glsl},
    }});
    nlohmann::json nodes = nodesBefore;
    nodes.push_back({{"block", "my_de"}});
    j["formula"]["nodes"] = nodes;
    return j.dump(2);
}

}  // namespace

// A whole DE's loops are the artist's, but every condition also counts a trip budget: a loop
// that never ends on its own still returns, after kMaxWholeDELoopTrips trips.
TEST(WholeDE, LoopsAreBoundedByATripBudget) {
    const Preset p = parsePreset(wholeDEPreset("float DE(vec3 p) {\n"
                                               "    float d = 0.0;\n"
                                               "    for (;;) { d += 1.0; }\n"
                                               "    while (true) { d += 1.0; }\n"
                                               "    return d * Radius;\n"
                                               "}\n"),
                                 "endless.json");
    const std::string code = generateFormulaGLSL(p.formula).code;
    EXPECT_NE(code.find("for (; ++fraktalDETrips < 10000;)"), std::string::npos) << code;
    EXPECT_NE(code.find("while ((true) && ++fraktalDETrips < 10000)"), std::string::npos) << code;
    test::glContext();
    const auto samples = gl::DEProbe(p.formula).evaluate(p.formula, std::vector<vec3>{vec3(0.0)});
    // The first loop spends the budget (9999 trips); the second stops at once.
    EXPECT_EQ(samples.at(0).distance, float(kMaxWholeDELoopTrips - 1) * float(p.formula.deFactor));
}

TEST(WholeDE, ValidationKeepsNodeBlocksStrictAndRefusesInconsistentPresets) {
    // A whole DE may declare functions, loop and #define; a node-list block still may not.
    EXPECT_NO_THROW(parsePreset(wholeDEPreset("#define K 2.0\nfloat f(float x) { for (int i = 0; i < 3; i++) x *= K; "
                                              "return x; }\nfloat DE(vec3 p) { return length(p) - f(Radius); }\n"),
                                "ok.json"));
    nlohmann::json node = nlohmann::json::parse(wholeDEPreset("float DE(vec3 p) { return length(p) - Radius; }\n"));
    node["formula"]["customBlocks"][0]["wholeDE"] = false;
    node["formula"]["customBlocks"][0]["glsl"] = "for (int i = 0; i < 3; i++) {}\nreturn length(p.xyz);";
    try {
        parsePreset(node.dump(), "node.json");
        FAIL() << "a loop in a node-list block";
    } catch (const PresetError& e) {
        EXPECT_NE(std::string(e.what()).find("loops ('for') are not allowed"), std::string::npos) << e.what();
    }
    auto reason = [](const std::string& text) {
        try {
            parsePreset(text, "whole.json");
            return std::string();
        } catch (const PresetError& e) {
            return std::string(e.what());
        }
    };
    EXPECT_NE(reason(wholeDEPreset("uniform float x;\nfloat DE(vec3 p) { return length(p) - x; }\n"))
                  .find("customBlocks[0].glsl: line 1: 'uniform' is not allowed in a whole DE"),
              std::string::npos);
    EXPECT_NE(reason(wholeDEPreset("float distanceTo(vec3 p) { return length(p); }\n"))
                  .find("no function `float DE(vec3 ...)`"),
              std::string::npos);
    EXPECT_NE(reason(wholeDEPreset("#version 120\nfloat DE(vec3 p) { return length(p); }\n")).find("'#version'"),
              std::string::npos);
    EXPECT_NE(reason(wholeDEPreset("float DE(vec3 p) { return texture(t, p.xy).r; }\n")).find("cannot read textures"),
              std::string::npos);
    // A whole DE computes the whole distance: nodes before it are an error naming the field.
    const std::string withNodes = reason(wholeDEPreset("float DE(vec3 p) { return length(p) - Radius; }\n",
                                                       nlohmann::json::array({{{"block", "abs_fold"}}})));
    EXPECT_NE(withNodes.find("formula.nodes[0]"), std::string::npos) << withNodes;
    EXPECT_NE(withNodes.find("is a whole DE"), std::string::npos) << withNodes;
}

// A compile error in a whole DE names the estimator and the line of its own code.
TEST(WholeDE, CompileErrorNamesTheEstimatorAndItsLine) {
    const Preset p = parsePreset(
        wholeDEPreset(
            "float DE(vec3 p) {\n    return length(p) - Radius;\n}\nfloat broken() { return undeclared_name; }\n"),
        "broken.json");
    test::glContext();
    try {
        gl::DEProbe probe(p.formula);
        FAIL() << "a whole DE that does not compile";
    } catch (const std::exception& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("estimator \"my_de\" (my_de), GLSL line 4"), std::string::npos) << what;
    }
}

// The whole DE's names are its own: globals and functions named like the generated shader's
// (iteration, pointW, repeatCell, formulaDE) and its parameters compile beside them.
TEST(WholeDE, ItsNamesCannotCollideWithTheGeneratedShader) {
    const Preset p = parsePreset(wholeDEPreset("int iteration;\n"
                                               "float pointW = 2.0;\n"
                                               "#define SHIFT 0.5\n"
                                               "float repeatCell(float x) { return x * pointW; }\n"
                                               "float formulaDE(vec3 p) { return length(p) - Radius; }\n"
                                               "float DE(vec3 p) {\n"
                                               "    iteration = 3;\n"
                                               "    return formulaDE(p) + repeatCell(SHIFT) - 1.0;\n"
                                               "}\n"),
                                 "names.json");
    const std::string code = generateFormulaGLSL(p.formula).code;
    EXPECT_NE(code.find("float fraktalDE_repeatCell(float x) { return x * fraktalDE_pointW; }"), std::string::npos)
        << code;
    EXPECT_NE(code.find("length(p) - u_est_Radius"), std::string::npos) << code;
    test::glContext();
    const auto samples = gl::DEProbe(p.formula).evaluate(p.formula, std::vector<vec3>{vec3(0.0, 0.0, 3.0)});
    // length 3 - radius 1, + 0.5 * 2 - 1.
    EXPECT_NEAR(samples.at(0).distance, 2.0 * p.formula.deFactor, 1e-5);
}
