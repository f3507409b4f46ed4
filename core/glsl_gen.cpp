#include "core/glsl_gen.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>
#include <stdexcept>

#include "core/shader_library.hpp"

namespace fraktal {

namespace {

std::string glslType(ParamType t) { return isScalar(t) ? "float" : "vec3"; }

// A number as a GLSL float literal, exact for the small integer degrees blocks declare.
std::string glslFloat(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    std::string s = buf;
    if (s.find_first_of(".e") == std::string::npos) s += ".0";
    return s;
}

int countLines(std::string_view s) { return int(std::count(s.begin(), s.end(), '\n')); }

std::string nodeFunctionName(int k) { return "fraktal_node" + std::to_string(k); }

// One function per node: uniforms, then the block's body under the node's own source number.
void emitNodeFunction(GlslEmitter& e, int k, const Node& node, const std::string& name, bool estimator) {
    const BlockDesc& b = *node.block;
    std::vector<GlslEmitter::Param> params;
    for (const ParamDecl& p : b.params)
        params.push_back(
            {glslType(p.type), estimator ? estimatorUniformName(p.name) : nodeUniformName(k, p.name), p.name});
    const std::string head =
        std::string(estimator ? "float " : "void ") + nodeFunctionName(k) +
        (estimator ? "(vec4 p, vec3 c, float degree, float surfaceLogR, float orbitGradient" : "(inout vec4 p, vec3 c");
    e.nodeFunction(k, b.id, name, head, params, b.glsl);
}

// The estimator's arguments before its parameters, as formulaEval passes them.
constexpr const char* kEstimatorArgs = "p, c, degree, surfaceLogR, orbitGradient";

std::string nodeCall(int k, const Node& node, bool estimator, const std::string& args = "") {
    std::string call = nodeFunctionName(k) + "(" + (!args.empty() ? args : estimator ? kEstimatorArgs : "p, c");
    for (const ParamDecl& p : node.block->params)
        call += ", " + (estimator ? estimatorUniformName(p.name) : nodeUniformName(k, p.name));
    return call + ")";
}

// The objects beside the fractal: a function per object (its kind's body under its own #line
// numbers, after the estimator's), then fraktalObjects(pos, d, escaped), which combines them with
// the estimate in order; it mirrors combineObjects() in core/scene_object.cpp. `escaped` is the
// escape-time membership's flag of an orbit outside, which an object sets or clears. Returns
// whether it emitted fraktalObjects (none without objects: the estimate is returned as it is).
bool emitObjects(GlslEmitter& e, const Formula& f, std::vector<std::string>& names) {
    std::string combine;
    const int first = int(f.nodes.size()) + 1;
    for (size_t j = 0; j < f.objects.size(); ++j) {
        const SceneObject& o = f.objects[j];
        names.push_back("object " + std::to_string(j + 1) + " \"" + std::string(o.block->label) + "\" (" +
                        std::string(o.block->id) + ")");
        if (!o.enabled) continue;
        const int k = int(j);
        std::vector<GlslEmitter::Param> params;
        std::string call = "fraktal_object" + std::to_string(j) + "(" + objectPlacementUniformName(k, "turn") +
                           " * (pos - " + objectPlacementUniformName(k, "center") + ")";
        for (const ParamDecl& p : o.block->params) {
            params.push_back({glslType(p.type), objectUniformName(k, p.name), p.name});
            call += ", " + objectUniformName(k, p.name);
        }
        call += ")";
        e.line("uniform vec3 " + objectPlacementUniformName(k, "center") + ";");
        e.line("uniform mat3 " + objectPlacementUniformName(k, "turn") + ";");
        e.nodeFunction(first + k, o.block->id, names.back(), "float fraktal_object" + std::to_string(j) + "(vec3 pos",
                       params, o.block->glsl);
        const std::string od = o.hollow ? "abs(" + call + ")" : call;
        switch (o.operation) {
            case ObjectOperation::Join:
                combine += "    { float o = " + od + "; d = min(d, o); if (o <= 0.0) escaped = false; }\n";
                break;
            case ObjectOperation::Intersect:
                combine += "    { float o = " + od + "; d = max(d, o); if (o > 0.0) escaped = true; }\n";
                break;
            case ObjectOperation::Carve:
                combine += "    { float o = " + od + "; d = max(d, -o); if (o <= 0.0) escaped = true; }\n";
                break;
        }
    }
    if (f.objects.empty()) return false;
    e.line("float fraktalObjects(vec3 pos, float d, inout bool escaped) {");
    e.out += combine;
    e.line("    return d;");
    e.line("}");
    return true;
}

void replaceMarker(std::string& text, std::string_view marker, const std::string& with) {
    replaceTemplateMarker(text, marker, with, "formula.glsl");
}

}  // namespace

void GlslEmitter::line(std::string_view s) {
    out += s;
    out += '\n';
}

int GlslEmitter::nextLine() const { return countLines(out) + 1; }

void GlslEmitter::restoreFormulaLines() { line("#line " + std::to_string(kFormulaLineBase + nextLine() + 1)); }

void GlslEmitter::nodeFunction(int k, std::string_view blockId, const std::string& name, const std::string& head,
                               const std::vector<Param>& params, std::string_view body) {
    line("// @node " + std::to_string(k) + " " + std::string(blockId) + ": " + name);
    std::string signature = head;
    for (const Param& p : params) {
        line("uniform " + p.type + " " + p.uniform + ";");
        signature += ", " + p.type + " " + std::string(p.name);
    }
    line(signature + ") {");
    line("#line " + std::to_string(kNodeLineStride * (k + 1) + 1));
    if (!body.empty() && body.front() == '\n') body.remove_prefix(1);
    out += body;
    if (!body.empty() && body.back() != '\n') out += '\n';
    restoreFormulaLines();
    line("}");
}

void replaceTemplateMarker(std::string& text, std::string_view marker, const std::string& with,
                           std::string_view templateName) {
    const size_t at = text.find(marker);
    if (at == std::string::npos)
        throw std::logic_error(std::string(templateName) + " lacks marker " + std::string(marker));
    const size_t end = text.find('\n', at);
    text.replace(at, (end == std::string::npos ? text.size() : end) - at, with);
}

std::string nodeUniformName(int nodeIndex, std::string_view param) {
    return "u_n" + std::to_string(nodeIndex) + "_" + std::string(param);
}
std::string estimatorUniformName(std::string_view param) { return "u_est_" + std::string(param); }
std::string objectUniformName(int objectIndex, std::string_view param) {
    return "u_o" + std::to_string(objectIndex) + "_" + std::string(param);
}
std::string objectPlacementUniformName(int objectIndex, std::string_view what) {
    return "u_op" + std::to_string(objectIndex) + "_" + std::string(what);
}

GeneratedFormula generateFormulaGLSL(const Formula& f) {
    GeneratedFormula g;
    std::string tmpl(shaderTemplate("formula.glsl"));
    // One line either way, so the template keeps its line numbers.
    replaceMarker(tmpl, "//@FRAKTAL_OPTIONS",
                  f.estimator.block->usesOrbitGradient() ? "#define FRAKTAL_ORBIT_GRADIENT" : "");
    constexpr std::string_view kHitRuleDefines[] = {"", "#define FRAKTAL_HIT_INSIDE_ONLY",
                                                    "#define FRAKTAL_HIT_INTERIOR_WALLS"};
    static_assert(std::size(kHitRuleDefines) == std::size(kHitRuleNames));
    replaceMarker(tmpl, "//@FRAKTAL_HIT_RULE", std::string(kHitRuleDefines[int(f.hitRule)]));
    const size_t nodesAt = tmpl.find("//@FRAKTAL_NODES");
    if (nodesAt == std::string::npos) throw std::logic_error("formula.glsl lacks //@FRAKTAL_NODES");

    // Text before the marker keeps its own line numbers; the node functions follow.
    GlslEmitter e;
    e.out = tmpl.substr(0, nodesAt);
    for (size_t k = 0; k < f.nodes.size(); ++k) {
        g.nodeNames.push_back(listedNodeName("node ", int(k), *f.nodes[k].block));
        if (f.nodes[k].enabled) emitNodeFunction(e, int(k), f.nodes[k], g.nodeNames.back(), false);
    }
    const int est = int(f.nodes.size());
    g.nodeNames.push_back(listedNodeName("estimator", -1, *f.estimator.block));
    emitNodeFunction(e, est, f.estimator, g.nodeNames.back(), true);
    const bool objects = emitObjects(e, f, g.nodeNames);

    std::string rest = tmpl.substr(tmpl.find('\n', nodesAt) + 1);
    std::string loop, remaining;
    for (size_t k = 0; k < f.nodes.size(); ++k) {
        const Node& n = f.nodes[k];
        if (!n.enabled) continue;
        std::string call = nodeCall(int(k), n, false) + ";";
        // The product of the power steps' degrees (P4::degree on the CPU), for the estimator; and,
        // in log2, that of the iterations an escaped orbit did not run and of all of them.
        if (n.block->raisesDegree()) {
            const std::string d = n.block->degreeParam >= 0
                                      ? nodeUniformName(int(k), n.block->params[size_t(n.block->degreeParam)].name)
                                      : glslFloat(n.block->fixedDegree);
            call += " degree *= " + d + ";";
            const std::string scheduleArgs = ", " + std::to_string(n.period) + ", " + std::to_string(n.phase) + ", " +
                                             std::to_string(n.start) + ", " + std::to_string(n.stop) + ")";
            const std::string runs = "iterationsRunBefore(n" + scheduleArgs;
            remaining += "    { float d = log2(" + d + "); remainingLog2 += float(" + runs +
                         " - iterationsRunBefore(iterations" + scheduleArgs + ") * d; allLog2 += float(" + runs +
                         ") * d; }\n";
        }
        if (!n.always())
            loop += "        if (" + n.glslCondition() + ") { " + call + " }\n";
        else
            loop += "        " + call + "\n";
    }
    if (!loop.empty()) loop.pop_back();
    if (!remaining.empty()) remaining.pop_back();
    replaceMarker(rest, "//@FRAKTAL_ORBIT_LOOP", loop);
    replaceMarker(rest, "//@FRAKTAL_LOOP", loop);
    replaceMarker(rest, "//@FRAKTAL_REMAINING_DEGREE", remaining);
    std::string estimate = "u_deFactor * " + nodeCall(est, f.estimator, true);
    if (f.hitRule == HitRule::InteriorWalls) estimate = "interiorWalls(" + estimate + ", escaped)";
    replaceMarker(
        rest, "//@FRAKTAL_ESTIMATE",
        objects ? "    return fraktalObjects(pos, " + estimate + ", escaped);" : "    return " + estimate + ";");
    const bool escapeTime = f.estimator.block->membership == Membership::EscapeTime;
    replaceMarker(rest, "//@FRAKTAL_MEMBERSHIP", escapeTime ? "    return !escaped;" : "    return d <= 0.0;");
    // The orbit gradient (estimators that read it): the estimate without it sets the difference
    // step; the orbit value is log r for escape-time estimates, else the estimate at w = 1.
    replaceMarker(
        rest, "//@FRAKTAL_RUNNING_ESTIMATE",
        "    float running = abs(" + nodeCall(est, f.estimator, true, "p, c, degree, surfaceLogR, 0.0") + ");");
    replaceMarker(
        rest, "//@FRAKTAL_ORBIT_VALUE",
        escapeTime ? "    return log(max(length(p.xyz), 1e-30));"
                   : "    return " + nodeCall(est, f.estimator, true, "vec4(p.xyz, 1.0), c, degree, 0.0, 0.0") + ";");
    e.restoreFormulaLines();
    e.out += rest;
    g.code = std::move(e.out);
    return g;
}

ShaderSource assembleShader(const GeneratedFormula& formula, std::string_view programName,
                            std::string_view programSource, std::string_view defines) {
    ShaderSource s;
    s.programName = programName;
    s.nodeNames = formula.nodeNames;
    s.text = "#version 450 core\n";
    s.text += defines;
    if (!defines.empty() && defines.back() != '\n') s.text += '\n';
    s.text += "#line " + std::to_string(kFormulaLineBase + 1) + "\n";
    s.text += formula.code;
    s.text += "\n#line 1\n";
    s.text += programSource;
    return s;
}

std::string ShaderSource::explainLog(std::string_view log) const {
    // Mesa: "101:3(5): error: ..."; glslang: "ERROR: 101:3: ...".
    static const std::regex where(R"((\d+):(\d+)(\(\d+\))?:)");
    std::string out;
    std::string text(log);
    std::sregex_iterator it(text.begin(), text.end(), where), end;
    size_t last = 0;
    for (; it != end; ++it) {
        const std::smatch& m = *it;
        const int line = std::stoi(m[2]);
        std::string where;
        if (line < kFormulaLineBase) {
            where = programName + " line " + std::to_string(line);
        } else if (line < kNodeLineStride) {
            where = "generated formula code line " + std::to_string(line - kFormulaLineBase);
        } else {
            const size_t node = size_t(line / kNodeLineStride - 1);
            if (node >= nodeNames.size()) continue;
            where = nodeNames[node] + ", GLSL line " + std::to_string(line % kNodeLineStride);
        }
        out += text.substr(last, m.position() - last);
        out += where + ":";
        last = m.position() + m.length();
    }
    out += text.substr(last);
    return out;
}

}  // namespace fraktal
