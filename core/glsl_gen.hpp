// GLSL generation from a formula's node list, with per-node #line markers so that a compile
// error names the node that caused it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/formula.hpp"

namespace fraktal {

// GLSL source-string numbers used by #line: the driver reports errors as "<source>:<line>".
inline constexpr int kSourceProgram = 0;    // the program's own template (march, probe...)
inline constexpr int kSourceFormula = 1;    // the formula template, shaders/formula.glsl
inline constexpr int kSourceFirstNode = 100;  // 100 + k: node k (the estimator comes last)

struct GeneratedFormula {
    std::string code;  // defines formulaDE(vec3, out vec4, out int) and DE(vec3)
    std::vector<std::string> nodeNames;  // index k: "node 3 (box_fold)"
};

GeneratedFormula generateFormulaGLSL(const Formula& f);

// Uniform names, shared by the generator and the uploader.
std::string nodeUniformName(int nodeIndex, std::string_view param);
std::string estimatorUniformName(std::string_view param);

// A complete shader: "#version 450 core", optional defines, the formula, then the program's
// own source (which calls DE / formulaDE).
struct ShaderSource {
    std::string text;
    std::string programName;
    std::vector<std::string> nodeNames;
    // Rewrites a driver's or glslang's log so that "101:3(5): error" reads
    // "node 1 (box_fold), line 3 of its GLSL: error".
    std::string explainLog(std::string_view log) const;
};

ShaderSource assembleShader(const GeneratedFormula& formula, std::string_view programName,
                            std::string_view programSource, std::string_view defines = {});

}  // namespace fraktal
