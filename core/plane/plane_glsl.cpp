#include "core/plane/plane_glsl.hpp"

#include <algorithm>
#include <stdexcept>

#include "core/shader_library.hpp"

namespace fraktal {

namespace {

std::string functionName(int k) { return "fraktal_pnode" + std::to_string(k); }

// The node's function, as the 3D generator writes its own (GlslEmitter::nodeFunction).
void emitNodeFunction(GlslEmitter& e, int k, const PlaneNode& node, const std::string& name, bool estimator) {
    const PlaneBlockDesc& b = *node.block;
    std::vector<GlslEmitter::Param> params;
    for (const ParamDecl& p : b.params) params.push_back({"float", planeUniformName(k, p.name), p.name});
    const std::string head = std::string(estimator ? "float " : "void ") + functionName(k) +
                             (estimator ? "(PlaneState s, real2 c" : "(inout PlaneState s, real2 c");
    e.nodeFunction(k, b.id, name, head, params, b.glsl);
}

std::string nodeCall(int k, const PlaneNode& node) {
    std::string call = functionName(k) + "(s, c";
    for (const ParamDecl& p : node.block->params) call += ", " + planeUniformName(k, p.name);
    return call + ")";
}

void replaceMarker(std::string& text, std::string_view marker, const std::string& with) {
    replaceTemplateMarker(text, marker, with, "plane_formula.glsl");
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

    GlslEmitter e;
    e.out = tmpl.substr(0, nodesAt);
    std::string startCalls, loopCalls;
    int k = 0;
    for (const PlaneNode& n : f.start) {
        g.nodeNames.push_back(listedNodeName("start node ", k, *n.block));
        if (n.enabled) {
            emitNodeFunction(e, k, n, g.nodeNames.back(), false);
            startCalls += "    " + nodeCall(k, n) + ";\n";
        }
        ++k;
    }
    for (size_t i = 0; i < f.nodes.size(); ++i, ++k) {
        const PlaneNode& n = f.nodes[i];
        g.nodeNames.push_back(listedNodeName("node ", int(i), *n.block));
        if (!n.enabled) continue;
        emitNodeFunction(e, k, n, g.nodeNames.back(), false);
        const std::string call = nodeCall(k, n) + ";";
        if (!n.always())
            loopCalls += "            if (" + n.glslCondition() + ") " + call + "\n";
        else
            loopCalls += "            " + call + "\n";
    }
    g.nodeNames.push_back(listedNodeName("estimator", -1, *f.estimator.block));
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
