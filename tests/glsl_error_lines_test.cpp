// A compile error lands on the line of the block's own code that caused it (core/glsl_log.hpp):
// the driver's log is read, the generated shader's line numbers are mapped back through the
// blocks' #line ranges, for a node-list GLSL block and for a whole DE an imported frag made, and
// NVIDIA's form of the same message lands alike. The log forms alone: glsl_log_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/gl/program.hpp"
#include "core/glsl_gen.hpp"
#include "core/glsl_log.hpp"
#include "core/scene/scene_import.hpp"
#include "core/shader_library.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

ShaderSource errorLinesProbeSource(const Formula& f) {
    return assembleShader(generateFormulaGLSL(f), "de_probe.comp", shaderTemplate("de_probe.comp"));
}

// The log the driver wrote for `f`, as explainLog rewrote it; empty when it compiled.
std::string driverErrorOf(const Formula& f) {
    try {
        gl::compileCompute(errorLinesProbeSource(f));
    } catch (const std::runtime_error& e) {
        return e.what();
    }
    return {};
}

// The 1-based line of `glsl` that holds `text`, 0 when none does.
int lineHolding(const std::string& glsl, const std::string& text) {
    const size_t at = glsl.find(text);
    return at == std::string::npos ? 0 : 1 + int(std::count(glsl.begin(), glsl.begin() + long(at), '\n'));
}

// The index in nodeNames of the block `id` (its #line range is kNodeLineStride * (index + 1)).
int nodeIndexOf(const ShaderSource& s, const std::string& id) {
    for (size_t k = 0; k < s.nodeNames.size(); ++k)
        if (s.nodeNames[k].find("(" + id + ")") != std::string::npos) return int(k);
    return -1;
}

// menger.frag imported, its whole DE with `from` replaced by `to`.
Preset importedMengerWith(const std::string& from, const std::string& to) {
    const Preset imported = importSceneFile(test::sourceDir() / "tests/data/frag_import/menger.frag").preset;
    nlohmann::json j = presetToJson(imported);
    std::string glsl = j["formula"]["customBlocks"][0]["glsl"];
    const size_t at = glsl.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    glsl.replace(at, from.size(), to);
    j["formula"]["customBlocks"][0]["glsl"] = glsl;
    return parsePreset(j.dump(), "menger_broken.json");
}

}  // namespace

// A node-list block whose code starts with a blank line, as a preset's JSON often writes it:
// the driver's error is on the block's line 3, where the undeclared name is, not line 2.
TEST(GlslErrorLines, NodeBlockErrorOnItsLineOnTheDriver) {
    nlohmann::json j = presetToJson(test::shippedPreset("mandelbox.json"));
    j["formula"]["customBlocks"] = nlohmann::json::array({{
        {"id", "lined_fold"},
        {"label", "Lined fold"},
        {"category", "fold"},
        {"params", {{{"name", "amount"}, {"default", 1.0}, {"min", 0.0}, {"max", 2.0}}}},
        {"glsl", "\n    p.xyz *= amount;\n    p.xyz += lined_undeclared;\n"},
    }});
    j["formula"]["nodes"].insert(j["formula"]["nodes"].begin() + 1, nlohmann::json{{"block", "lined_fold"}});
    const Preset p = parsePreset(j.dump(), "lined.json");
    test::glContext();
    const std::string log = driverErrorOf(p.formula);
    ASSERT_FALSE(log.empty()) << "a block using an undeclared name compiled";
    const std::vector<SourceError> errors = blockErrorsInExplainedLog(log, "lined_fold");
    ASSERT_FALSE(errors.empty()) << log;
    EXPECT_EQ(errors[0].line, 3) << log;
    EXPECT_NE(errors[0].message.find("lined_undeclared"), std::string::npos) << log;
    // Warnings are no errors; no other block's errors are this one's.
    EXPECT_TRUE(
        blockErrorsInExplainedLog("node 2 \"Lined fold\" (lined_fold), GLSL line 1: warning: unused", "lined_fold")
            .empty());
    EXPECT_TRUE(blockErrorsInExplainedLog(log, "box_fold").empty()) << log;
}

// An imported frag's whole DE: an error the driver finds deep in it lands on the line of the
// code the editor shows, for Mesa's log (the driver here) and for NVIDIA's form of the same
// message.
TEST(GlslErrorLines, WholeDEErrorOnItsLineOnTheDriverAndInNvidiasForm) {
    const std::string good = "return boxDistance(z, vec3(1.0)) / w;";
    const Preset p = importedMengerWith(good, "return boxDistance(z, vec3(1.0)) / w + twist_undeclared;");
    const std::string glsl = p.formula.customBlocks.at(0)->definition().glsl;
    const std::string id = p.formula.customBlocks.at(0)->definition().id;
    const int line = lineHolding(glsl, "twist_undeclared");
    ASSERT_GT(line, 20) << "the DE's return sits below the helpers:\n" << glsl;

    test::glContext();
    const std::string log = driverErrorOf(p.formula);
    ASSERT_FALSE(log.empty()) << "a whole DE using an undeclared name compiled";
    const std::vector<SourceError> errors = blockErrorsInExplainedLog(log, id);
    ASSERT_FALSE(errors.empty()) << log;
    EXPECT_EQ(errors[0].line, line) << log;
    EXPECT_NE(errors[0].message.find("twist_undeclared"), std::string::npos) << log;

    // NVIDIA writes "0(LINE) : error C1008: ..." with the generated shader's line.
    const ShaderSource s = errorLinesProbeSource(p.formula);
    const int node = nodeIndexOf(s, id);
    ASSERT_GE(node, 0);
    const std::string nvidia = "0(" + std::to_string(kNodeLineStride * (node + 1) + line) +
                               ") : error C1008: undefined variable \"twist_undeclared\"\n";
    const std::vector<SourceError> fromNvidia = blockErrorsInExplainedLog(s.explainLog(nvidia), id);
    ASSERT_EQ(fromNvidia.size(), 1u) << s.explainLog(nvidia);
    EXPECT_EQ(fromNvidia[0], (SourceError{line, "error C1008: undefined variable \"twist_undeclared\""}));

    // The code fixed compiles: no error is left on any line.
    EXPECT_TRUE(driverErrorOf(importedMengerWith(good, good).formula).empty());
}
