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
//   10000 * (k + 1) + n    line n of node k's GLSL (the estimator is the last node, the objects
//                          beside the fractal follow it, then each combined fractal's nodes)
inline constexpr int kFormulaLineBase = 5000;
inline constexpr int kNodeLineStride = 10000;

struct GeneratedFormula {
    std::string
        code;  // defines formulaEval(vec3, out vec4, out int, out bool), formulaDE(vec3, out vec4, out int), DE(vec3)
    std::vector<std::string> nodeNames;  // index k: listedNodeName, e.g. `node 3 "Box fold" (box_fold)`
};

// How compile errors name a node: as the editor's node list shows it, numbered from 1 with its
// label, then the id a preset file uses: `node 2 "Box fold" (box_fold)`; with index < 0 no number
// (`estimator "Box" (box)`). `what` is "node ", "start node " or "estimator".
template <class Desc>
std::string listedNodeName(std::string_view what, int index, const Desc& block) {
    std::string name(what);
    if (index >= 0) name += std::to_string(index + 1);
    return name + " \"" + std::string(block.label) + "\" (" + std::string(block.id) + ")";
}

GeneratedFormula generateFormulaGLSL(const Formula& f);

// What the 3D generator and the 2D one (core/plane/plane_glsl.cpp) share: formula source text
// that tracks its own line numbers (string 1), so that after a node's #line block the numbering
// of the template can be restored, and the per-node function under its own #line range.
struct GlslEmitter {
    struct Param {
        std::string type;       // "float", "vec3"
        std::string uniform;    // the uniform the call passes
        std::string_view name;  // the parameter's name inside the body
    };

    std::string out;

    void line(std::string_view s);
    int nextLine() const;
    void restoreFormulaLines();
    // "// @node k id: name", a uniform per parameter, then `head, <type> <name>...) {` with the
    // block's body under the node's own #line numbers (kNodeLineStride * (k + 1) + 1).
    // `head` opens the signature up to the state and point, e.g. "void fraktal_node3(inout vec4
    // p, vec3 c".
    void nodeFunction(int k, std::string_view blockId, const std::string& name, const std::string& head,
                      const std::vector<Param>& params, std::string_view body);
};

// Replaces the line holding `marker` in a formula template with `with`; throws std::logic_error
// naming the template when the marker is missing.
void replaceTemplateMarker(std::string& text, std::string_view marker, const std::string& with,
                           std::string_view templateName);

// The prefix of a whole DE's top-level names in the fractal of that suffix (core/whole_de.hpp).
std::string wholeDEPrefix(std::string_view fractal);
// Uniform names, shared by the generator and the uploader. `fractal` is fractalSuffix(index):
// "" for the first fractal, "_f1", "_f2"... for those combined with it (Formula::fractals).
std::string fractalSuffix(size_t index);
std::string nodeUniformName(int nodeIndex, std::string_view param, std::string_view fractal = "");
std::string estimatorUniformName(std::string_view param, std::string_view fractal = "");
// A fractal's own uniforms (shaders/formula_fractal.glsl): "iterations", "bailout", "deFactor",
// and its placement's "fractalCenter", "fractalTurn", "fractalScale", "fractalRepeat".
std::string fractalUniformName(std::string_view what, std::string_view fractal);
// An object's parameter, and its placement ("center", "turn": the mat3 localFromWorld, "repeat").
std::string objectUniformName(int objectIndex, std::string_view param);
std::string objectPlacementUniformName(int objectIndex, std::string_view what);

// A complete shader: "#version 450 core", optional defines, the formula, then the program's
// own source (which calls DE / formulaDE).
struct ShaderSource {
    std::string text;
    std::string programName;
    std::vector<std::string> nodeNames;
    // Rewrites a driver's or glslang's log (Mesa's, NVIDIA's, glslang's forms: parseShaderLog) so
    // that "0:20003(5): error: ..." or "0(20003) : error C1008: ..." reads
    // "node 1 "Box fold" (box_fold), GLSL line 3: error...", one message a line.
    std::string explainLog(std::string_view log) const;
};

ShaderSource assembleShader(const GeneratedFormula& formula, std::string_view programName,
                            std::string_view programSource, std::string_view defines = {});

}  // namespace fraktal
