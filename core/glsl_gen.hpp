// GLSL generation from a formula's node list, with per-node #line markers so that a compile
// error names the node that caused it.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/formula.hpp"

namespace fraktal {

// Where a line of an assembled shader came from is encoded in its #line number, because Mesa
// reports every error as source string 0 whatever #line says (glslang honours both):
//   lines 1 .. 4999        the program's own template (march, probe...)
//   5000 + n               line n of the generated formula code (shaders/formula.glsl)
//   10000 * (k + 1) + n    line n of node k's GLSL (the estimator is the last node)
inline constexpr int kFormulaLineBase = 5000;
inline constexpr int kNodeLineStride = 10000;

struct GeneratedFormula {
    std::string code;  // defines formulaEval(vec3, out vec4, out int, out bool), formulaDE(vec3, out vec4, out int), DE(vec3)
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
    // Rewrites a driver's or glslang's log so that "0:20003(5): error" reads
    // "node 1 (box_fold), GLSL line 3: error".
    std::string explainLog(std::string_view log) const;
};

ShaderSource assembleShader(const GeneratedFormula& formula, std::string_view programName,
                            std::string_view programSource, std::string_view defines = {});

}  // namespace fraktal
