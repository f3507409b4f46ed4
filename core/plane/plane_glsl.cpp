#include "core/plane/plane_glsl.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/shader_library.hpp"

namespace fraktal {

namespace {

int countLines(std::string_view s) { return int(std::count(s.begin(), s.end(), '\n')); }

// Text with the running line number of the formula source, so that after a node's own #line
// block the template's numbering is restored (see kFormulaLineBase in core/glsl_gen.hpp).
struct Emitter {
    std::string out;
    void line(std::string_view s) {
        out += s;
        out += '\n';
    }
    void restoreFormulaLines() { line("#line " + std::to_string(kFormulaLineBase + countLines(out) + 2)); }
};

std::string functionName(int k) { return "fraktal_pnode" + std::to_string(k); }

void emitNodeFunction(Emitter& e, int k, const PlaneNode& node, const std::string& name, bool estimator) {
    const PlaneBlockDesc& b = *node.block;
    e.line("// @node " + std::to_string(k) + " " + std::string(b.id) + ": " + name);
    std::string signature = std::string(estimator ? "float " : "void ") + functionName(k) +
                            (estimator ? "(PlaneState s, real2 c" : "(inout PlaneState s, real2 c");
    for (const ParamDecl& p : b.params) {
        e.line("uniform float " + planeUniformName(k, p.name) + ";");
        signature += ", float " + std::string(p.name);
    }
    e.line(signature + ") {");
    e.line("#line " + std::to_string(kNodeLineStride * (k + 1) + 1));
    std::string_view body = b.glsl;
    if (!body.empty() && body.front() == '\n') body.remove_prefix(1);
    e.out += body;
    if (!body.empty() && body.back() != '\n') e.out += '\n';
    e.restoreFormulaLines();
    e.line("}");
}

std::string nodeCall(int k, const PlaneNode& node) {
    std::string call = functionName(k) + "(s, c";
    for (const ParamDecl& p : node.block->params) call += ", " + planeUniformName(k, p.name);
    return call + ")";
}

void replaceMarker(std::string& text, std::string_view marker, const std::string& with) {
    const size_t at = text.find(marker);
    if (at == std::string::npos) throw std::logic_error("plane_formula.glsl lacks marker " + std::string(marker));
    const size_t end = text.find('\n', at);
    text.replace(at, (end == std::string::npos ? text.size() : end) - at, with);
}

}  // namespace

std::string planeUniformName(int nodeIndex, std::string_view param) {
    return "u_pn" + std::to_string(nodeIndex) + "_" + std::string(param);
}

GeneratedFormula generatePlaneGLSL(const PlaneFormula& f) {
    GeneratedFormula g;
    const std::string tmpl(shaderTemplate("plane_formula.glsl"));
    const size_t nodesAt = tmpl.find("//@PLANE_NODES");
    if (nodesAt == std::string::npos) throw std::logic_error("plane_formula.glsl lacks //@PLANE_NODES");

    Emitter e;
    e.out = tmpl.substr(0, nodesAt);
    std::string startCalls, loopCalls;
    int k = 0;
    for (const PlaneNode& n : f.start) {
        g.nodeNames.push_back("start node " + std::to_string(k) + " (" + std::string(n.block->id) + ")");
        if (n.enabled) {
            emitNodeFunction(e, k, n, g.nodeNames.back(), false);
            startCalls += "    " + nodeCall(k, n) + ";\n";
        }
        ++k;
    }
    for (size_t i = 0; i < f.nodes.size(); ++i, ++k) {
        const PlaneNode& n = f.nodes[i];
        g.nodeNames.push_back("node " + std::to_string(i) + " (" + std::string(n.block->id) + ")");
        if (!n.enabled) continue;
        emitNodeFunction(e, k, n, g.nodeNames.back(), false);
        const std::string call = nodeCall(k, n) + ";";
        if (n.period > 1)
            loopCalls += "            if (i % " + std::to_string(n.period) + " == " + std::to_string(n.phase) + ") " + call + "\n";
        else
            loopCalls += "            " + call + "\n";
    }
    g.nodeNames.push_back("estimator (" + std::string(f.estimator.block->id) + ")");
    emitNodeFunction(e, k, f.estimator, g.nodeNames.back(), true);

    std::string rest = tmpl.substr(tmpl.find('\n', nodesAt) + 1);
    if (!startCalls.empty()) startCalls.pop_back();
    if (!loopCalls.empty()) loopCalls.pop_back();
    replaceMarker(rest, "//@PLANE_START", startCalls);
    replaceMarker(rest, "//@PLANE_LOOP", loopCalls);
    replaceMarker(rest, "//@PLANE_ESTIMATE", "    float d = " + nodeCall(k, f.estimator) + ";");
    const char* inside = "    inside = !s.escaped;";  // PlaneMembership::NotEscaped; see fraktal::planeInside
    if (f.estimator.block->membership == PlaneMembership::Region) inside = "    inside = !s.escaped && d <= 0.0;";
    if (f.estimator.block->membership == PlaneMembership::Captured) inside = "    inside = s.captured;";
    replaceMarker(rest, "//@PLANE_INSIDE", inside);
    e.restoreFormulaLines();
    e.out += rest;
    g.code = std::move(e.out);
    return g;
}

}  // namespace fraktal
