// Generated GLSL compiles with glslang (the reference compiler) for every block and preset,
// and a compile error names the node that caused it.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "core/gl/program.hpp"
#include "core/shader_library.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

struct ToolResult {
    int status;
    std::string output;
};

// Runs glslangValidator on a compute shader; returns its exit status and output. The shader is
// written in a folder of this process's own: parallel runs (ctest -j, gtest shards) write the
// same names, and one run would otherwise validate, or remove, another's file.
ToolResult glslang(const ShaderSource& s, const std::string& name) {
    static const test::Sandbox sandbox("fraktal_glsl_test_");
    const auto file = sandbox.dir / (name + ".comp");
    std::ofstream(file) << s.text;
    const std::string command = std::string(FRAKTAL_GLSLANG) + " " + file.string() + " 2>&1";
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char buf[512];
    while (pipe && fgets(buf, sizeof buf, pipe)) out += buf;
    const int status = pipe ? pclose(pipe) : -1;
    return {status, out};
}

ShaderSource probeSource(const Formula& f) {
    return assembleShader(generateFormulaGLSL(f), "de_probe.comp", shaderTemplate("de_probe.comp"));
}

Formula withOneBlock(const BlockDesc& b) {
    Formula f;
    if (b.isEstimator()) {
        f.estimator = Node::make(b);
    } else {
        f.nodes = {Node::make(b)};
        f.estimator = Node::make(*findBlock("sphere"));
    }
    return f;
}

// A block with a GLSL error, to see the error routed to its node.
constexpr std::array<ParamDecl, 1> kBrokenParams{ParamDecl{"amount", ParamType::Float, {1, 0, 0}, 0, 2, "test"}};
void brokenApply(P4&, const vec3&, Args) {}
// Its code starts with a blank line: the undeclared name is on its line 3, which the error names.
const BlockDesc kBroken{.id = "broken_block",
                        .label = "Broken",
                        .help = "test",
                        .category = Category::Fold,
                        .params = kBrokenParams,
                        .glsl = "\n    p.xyz *= amount;\n    p.xyz += no_such_variable;\n",
                        .apply = &brokenApply};

}  // namespace

TEST(GlslCompile, EveryBlockWithGlslang) {
    for (const BlockDesc& b : allBlocks()) {
        const ToolResult r = glslang(probeSource(withOneBlock(b)), std::string(b.id));
        EXPECT_EQ(r.status, 0) << b.id << ":\n" << r.output;
    }
}

TEST(GlslCompile, EveryPresetWithGlslangAndDriver) {
    test::glContext();
    for (const auto& path : test::shippedPresets()) {
        const Preset p = loadPreset(path);
        const ShaderSource s = probeSource(p.formula);
        const ToolResult r = glslang(s, path.stem().string());
        EXPECT_EQ(r.status, 0) << path << ":\n" << r.output;
        EXPECT_NO_THROW(gl::compileCompute(s)) << path;
    }
}

TEST(GlslCompile, ErrorNamesTheNodeOnTheDriver) {
    test::glContext();
    Formula f = withOneBlock(*findBlock("box_fold"));
    f.nodes.push_back(Node::make(kBroken));
    try {
        gl::compileCompute(probeSource(f));
        FAIL() << "a shader using an undeclared variable compiled";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("node 2 \"Broken\" (broken_block), GLSL line 3"), std::string::npos) << message;
        EXPECT_NE(message.find("no_such_variable"), std::string::npos) << message;
    }
}

TEST(GlslCompile, ErrorNamesTheNodeWithGlslang) {
    Formula f = withOneBlock(*findBlock("box_fold"));
    f.nodes.push_back(Node::make(kBroken));
    const ShaderSource s = probeSource(f);
    const ToolResult r = glslang(s, "broken");
    EXPECT_NE(r.status, 0);
    const std::string explained = s.explainLog(r.output);
    EXPECT_NE(explained.find("node 2 \"Broken\" (broken_block), GLSL line 3"), std::string::npos) << explained;
}

// Parameters are uniforms: values do not change the generated code; structure does.
TEST(GlslCompile, OnlyStructureChangesTheCode) {
    const Preset p = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    Formula edited = p.formula;
    edited.nodes[0].values[0].x = 1.7;
    edited.iterations = 30;
    edited.bailout = 9.0;
    EXPECT_EQ(generateFormulaGLSL(edited).code, generateFormulaGLSL(p.formula).code);
    EXPECT_EQ(edited.structureKey(), p.formula.structureKey());

    Formula reordered = p.formula;
    std::swap(reordered.nodes[0], reordered.nodes[1]);
    EXPECT_NE(generateFormulaGLSL(reordered).code, generateFormulaGLSL(p.formula).code);
    EXPECT_NE(reordered.structureKey(), p.formula.structureKey());
    Formula disabled = p.formula;
    disabled.nodes[3].enabled = false;
    EXPECT_NE(disabled.structureKey(), p.formula.structureKey());
}
