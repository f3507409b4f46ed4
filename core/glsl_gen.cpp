#include "core/glsl_gen.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>

#include "core/glsl_log.hpp"
#include "core/shader_library.hpp"
#include "core/whole_de.hpp"

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

// One fractal's names: node k's function and uniforms carry the fractal's suffix (fractalSuffix);
// `line` numbers its functions' #line ranges, which run on across the fractals and objects.
struct FractalNames {
    std::string suffix;
    int firstLine = 0;

    std::string function(int k) const { return "fraktal_node" + std::to_string(k) + suffix; }
    std::string uniform(int k, std::string_view param, bool estimator) const {
        return estimator ? estimatorUniformName(param, suffix) : nodeUniformName(k, param, suffix);
    }
};

// A whole-DE estimator (core/whole_de.hpp): its parameters' uniforms and a trip counter, its code
// at global scope under the node's own source numbers (its names prefixed, its loops bounded),
// then the estimator function the fractal calls: the counter, the orbit trap and init() reset,
// the DE at the fractal's point.
void emitWholeDE(GlslEmitter& e, const FractalNames& names, int k, const BlockDesc& b, const std::string& name) {
    const WholeDEScan scan = scanWholeDE(b.glsl);
    const std::string prefix = wholeDEPrefix(names.suffix);
    const std::string trips = "fraktalDETrips" + names.suffix;
    e.line("// @node " + std::to_string(k) + " " + std::string(b.id) + ": " + name);
    std::vector<std::string> params;
    for (const ParamDecl& p : b.params) {
        params.emplace_back(p.name);
        e.line("uniform " + glslType(p.type) + " " + names.uniform(k, p.name, true) + ";");
    }
    e.line("int " + trips + ";");
    e.line("#line " + std::to_string(kNodeLineStride * (k + 1) + 1));
    const std::string code = wholeDEShaderCode(
        b.glsl, scan, prefix, [&](std::string_view p) { return names.uniform(k, p, true); }, params, trips);
    e.out += code;
    if (!code.empty() && code.back() != '\n') e.out += '\n';
    e.restoreFormulaLines();
    e.line("float " + names.function(k) + "(vec4 p, vec3 c, float degree, float surfaceLogR, float orbitGradient) {");
    e.line("    " + trips + " = 0;");
    if (scan.hasOrbitTrap) e.line("    " + prefix + "orbitTrap = vec4(10000.0);");
    if (scan.hasInit) e.line("    " + prefix + "init();");
    // The Slicer raytracer's DE(vec3 pos, int type) draws the object at type 0.
    const bool typed = scan.deParameters.find(',') != std::string::npos;
    e.line("    return " + prefix + "DE(p.xyz" + (typed ? ", 0" : "") + ");");
    e.line("}");
}

// One function per node: uniforms, then the block's body under the node's own source number.
void emitNodeFunction(GlslEmitter& e, const FractalNames& names, int k, const Node& node, const std::string& name,
                      bool estimator) {
    const BlockDesc& b = *node.block;
    if (estimator && b.wholeDE) return emitWholeDE(e, names, k, b, name);
    std::vector<GlslEmitter::Param> params;
    for (const ParamDecl& p : b.params)
        params.push_back({glslType(p.type), names.uniform(k, p.name, estimator), p.name});
    const std::string head =
        std::string(estimator ? "float " : "void ") + names.function(k) +
        (estimator ? "(vec4 p, vec3 c, float degree, float surfaceLogR, float orbitGradient" : "(inout vec4 p, vec3 c");
    e.nodeFunction(names.firstLine + k, b.id, name, head, params, b.glsl);
}

// The estimator's arguments before its parameters, as fractalEval passes them.
constexpr const char* kEstimatorArgs = "p, c, degree, surfaceLogR, orbitGradient";

std::string nodeCall(const FractalNames& names, int k, const Node& node, bool estimator, const std::string& args = "") {
    std::string call = names.function(k) + "(" + (!args.empty() ? args : estimator ? kEstimatorArgs : "p, c");
    // A whole DE reads its parameters' uniforms directly (emitWholeDE).
    if (!node.block->wholeDE)
        for (const ParamDecl& p : node.block->params) call += ", " + names.uniform(k, p.name, estimator);
    return call + ")";
}

// The objects beside the fractal: a function per object (its kind's body under its own #line
// numbers, after the estimator's), then fraktalObjects(pos, d, escaped, surface), which combines
// them with the estimate in order; it mirrors combineObjects() in core/scene_object.cpp. `escaped`
// is the escape-time membership's flag of an orbit outside, which an object sets or clears;
// `surface` becomes the index of the object whose distance the result is. Returns whether it
// emitted fraktalObjects (none without objects: the estimate is returned as it is).
bool emitObjects(GlslEmitter& e, const Formula& f, int first, std::vector<std::string>& names) {
    std::string combine;
    for (size_t j = 0; j < f.objects.size(); ++j) {
        const SceneObject& o = f.objects[j];
        names.push_back("object " + std::to_string(j + 1) + " \"" + std::string(o.block->label) + "\" (" +
                        std::string(o.block->id) + ")");
        if (!o.enabled) continue;
        const int k = int(j);
        std::vector<GlslEmitter::Param> params;
        std::string call = "fraktal_object" + std::to_string(j) + "(repeatCell(" +
                           objectPlacementUniformName(k, "turn") + " * (pos - " +
                           objectPlacementUniformName(k, "center") + "), " + objectPlacementUniformName(k, "repeat") +
                           ")";
        for (const ParamDecl& p : o.block->params) {
            params.push_back({glslType(p.type), objectUniformName(k, p.name), p.name});
            call += ", " + objectUniformName(k, p.name);
        }
        call += ")";
        e.line("uniform vec3 " + objectPlacementUniformName(k, "center") + ";");
        e.line("uniform mat3 " + objectPlacementUniformName(k, "turn") + ";");
        e.line("uniform vec3 " + objectPlacementUniformName(k, "repeat") + ";");
        e.nodeFunction(first + k, o.block->id, names.back(), "float fraktal_object" + std::to_string(j) + "(vec3 pos",
                       params, o.block->glsl);
        const std::string od = o.hollow ? "abs(" + call + ")" : call;
        // `taken`: the object's distance as the operation takes it; where it wins, the result is
        // the object's surface.
        const std::string wins = "if (wins) { d = taken; surface = " + std::to_string(k) + "; } }\n";
        // An intersecting object is a limit box: its faces are the fractal's inside, cut open,
        // and keep the surface before it (Mandelbulber2 colours a limit box's cut by the fractal).
        const std::string cuts = "if (wins) d = taken; }\n";
        switch (o.operation) {
            case ObjectOperation::Join:
                combine += "    { float o = " + od +
                           "; float taken = o; bool wins = o < d; if (o <= 0.0) escaped = false; " + wins;
                break;
            case ObjectOperation::Intersect:
                combine += "    { float o = " + od +
                           "; float taken = o; bool wins = o > d; if (o > 0.0) escaped = true; " + cuts;
                break;
            case ObjectOperation::Carve:
                combine += "    { float o = " + od +
                           "; float taken = -o; bool wins = taken > d; if (o <= 0.0) escaped = true; " + wins;
                break;
        }
    }
    if (f.objects.empty()) return false;
    e.line("float fraktalObjects(vec3 pos, float d, inout bool escaped, inout int surface) {");
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
    // The body as written, a leading blank line too: its line n is the block's line n.
    line("#line " + std::to_string(kNodeLineStride * (k + 1) + 1));
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

std::string wholeDEPrefix(std::string_view fractal) { return "fraktalDE" + std::string(fractal) + "_"; }
std::string fractalSuffix(size_t index) { return index == 0 ? "" : "_f" + std::to_string(index); }
std::string nodeUniformName(int nodeIndex, std::string_view param, std::string_view fractal) {
    return "u_n" + std::to_string(nodeIndex) + "_" + std::string(param) + std::string(fractal);
}
std::string estimatorUniformName(std::string_view param, std::string_view fractal) {
    return "u_est_" + std::string(param) + std::string(fractal);
}
std::string fractalUniformName(std::string_view what, std::string_view fractal) {
    return "u_" + std::string(what) + std::string(fractal);
}
std::string objectUniformName(int objectIndex, std::string_view param) {
    return "u_o" + std::to_string(objectIndex) + "_" + std::string(param);
}
std::string objectPlacementUniformName(int objectIndex, std::string_view what) {
    return "u_op" + std::to_string(objectIndex) + "_" + std::string(what);
}

namespace {

// The node functions of one fractal, numbered from names.firstLine, listed in `nodeNames` as
// `what` + the node's listed name.
void emitFractalNodes(GlslEmitter& e, const Formula& f, const FractalNames& names, const std::string& what,
                      std::vector<std::string>& nodeNames) {
    for (size_t k = 0; k < f.nodes.size(); ++k) {
        nodeNames.push_back(what + listedNodeName("node ", int(k), *f.nodes[k].block));
        if (f.nodes[k].enabled) emitNodeFunction(e, names, int(k), f.nodes[k], nodeNames.back(), false);
    }
    nodeNames.push_back(what + listedNodeName("estimator", -1, *f.estimator.block));
    emitNodeFunction(e, names, int(f.nodes.size()), f.estimator, nodeNames.back(), true);
}

// shaders/formula_fractal.glsl for one fractal: its uniforms, orbit, membership and estimate,
// fractalEval<suffix> and fractalInside<suffix>.
std::string fractalInstance(const Formula& f, const FractalNames& names, HitRule hitRule) {
    std::string text(shaderTemplate("formula_fractal.glsl"));
    auto replace = [&text](std::string_view marker, const std::string& with) {
        replaceTemplateMarker(text, marker, with, "formula_fractal.glsl");
    };
    const bool wholeDE = f.estimator.block->wholeDE;
    replace("//@FRAKTAL_FRACTAL_OPTIONS", f.estimator.block->usesOrbitGradient() ? "#define FRAKTAL_ORBIT_GRADIENT@F"
                                          : wholeDE                              ? "#define FRAKTAL_WHOLE_DE@F"
                                                                                 : "");
    std::string loop, remaining;
    for (size_t k = 0; k < f.nodes.size(); ++k) {
        const Node& n = f.nodes[k];
        if (!n.enabled) continue;
        std::string call = nodeCall(names, int(k), n, false) + ";";
        // The product of the power steps' degrees (P4::degree on the CPU), for the estimator; and,
        // in log2, that of the iterations an escaped orbit did not run and of all of them.
        if (n.block->raisesDegree()) {
            const std::string d = n.block->degreeParam >= 0
                                      ? names.uniform(int(k), n.block->params[size_t(n.block->degreeParam)].name, false)
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
    replace("//@FRAKTAL_ORBIT_LOOP", loop);
    replace("//@FRAKTAL_LOOP", loop);
    replace("//@FRAKTAL_REMAINING_DEGREE", remaining);
    const int est = int(f.nodes.size());
    std::string estimate = "    float d = u_deFactor@F * " + nodeCall(names, est, f.estimator, true) + ";\n";
    // A whole DE's orbit trap: FragM's x, y, z minima as they are, its w (r squared) as r.
    if (wholeDE && scanWholeDE(f.estimator.block->glsl).hasOrbitTrap) {
        const std::string t = wholeDEPrefix(names.suffix) + "orbitTrap";
        estimate += "    trap = vec4(" + t + ".xyz, sqrt(max(" + t + ".w, 0.0)));\n";
    }
    if (hitRule == HitRule::InteriorWalls)
        estimate +=
            "    d = interiorWalls(d, fractalInside@F(d, escaped), hitThreshold * "
            "abs(u_fractalScale@F));\n";
    replace("//@FRAKTAL_ESTIMATE", estimate + "    return d / u_fractalScale@F;");
    const bool escapeTime = f.estimator.block->membership == Membership::EscapeTime;
    replace("//@FRAKTAL_MEMBERSHIP", escapeTime ? "    return !escaped;" : "    return d <= 0.0;");
    // The orbit gradient (estimators that read it): the estimate without it sets the difference
    // step; the orbit value is log r for escape-time estimates, else the estimate at w = 1.
    replace(
        "//@FRAKTAL_RUNNING_ESTIMATE",
        "    float running = abs(" + nodeCall(names, est, f.estimator, true, "p, c, degree, surfaceLogR, 0.0") + ");");
    replace("//@FRAKTAL_ORBIT_VALUE",
            escapeTime ? "    return log(max(length(vec4(p.xyz, pointW)), 1e-30));"
                       : "    return " +
                             nodeCall(names, est, f.estimator, true, "vec4(p.xyz, 1.0), c, degree, 0.0, 0.0") + ";");
    for (size_t at = text.find("@F"); at != std::string::npos; at = text.find("@F", at + names.suffix.size()))
        text.replace(at, 2, names.suffix);
    return text;
}

// formulaEval's body: the first fractal, each combined one in order (the trap and count of the
// one that sets the distance kept, memberships combined as a flag), then the objects. Mirrors
// evaluate() in core/formula.cpp.
std::string combineFractals(const Formula& f, bool objects) {
    std::string s =
        "    surface = FRAKTAL_FRACTAL_SURFACE;\n    float d = fractalEval(pos, trap, iterations, escaped);\n";
    if (!f.fractals.empty()) s += "    bool inside = fractalInside(d, escaped);\n";
    for (size_t j = 0; j < f.fractals.size(); ++j) {
        const CombinedFractal& c = f.fractals[j];
        if (!c.enabled) continue;
        const std::string suffix = fractalSuffix(j + 1);
        s += "    {\n        vec4 t; int n; bool e;\n        float o = fractalEval" + suffix +
             "(pos, t, n, e);\n        bool oInside = fractalInside" + suffix + "(o, e);\n";
        switch (c.operation) {
            case ObjectOperation::Join:
                s += "        bool taken = o < d;\n        d = min(d, o);\n        inside = inside || oInside;\n";
                break;
            case ObjectOperation::Intersect:
                s += "        bool taken = o > d;\n        d = max(d, o);\n        inside = inside && oInside;\n";
                break;
            case ObjectOperation::Carve:
                // An escape-time estimate is no distance inside its set (evaluate() in core/formula.hpp).
                s += c.formula.estimator.block->membership == Membership::EscapeTime
                         ? "        float cut = oInside ? 1.5 * hitThreshold : -o;\n"
                         : "        float cut = -o;\n";
                s += "        bool taken = cut > d;\n        d = max(d, cut);\n        inside = inside && !oInside;\n";
                break;
        }
        s += "        if (taken) { trap = t; iterations = n; }\n    }\n";
    }
    if (!f.fractals.empty()) s += "    escaped = !inside;\n";
    s += objects ? "    return fraktalObjects(pos, d, escaped, surface);" : "    return d;";
    return s;
}

}  // namespace

GeneratedFormula generateFormulaGLSL(const Formula& f) {
    GeneratedFormula g;
    std::string tmpl(shaderTemplate("formula.glsl"));
    // One line either way, so the template keeps its line numbers.
    constexpr std::string_view kHitRuleDefines[] = {"", "#define FRAKTAL_HIT_INSIDE_ONLY",
                                                    "#define FRAKTAL_HIT_INTERIOR_WALLS"};
    static_assert(std::size(kHitRuleDefines) == std::size(kHitRuleNames));
    replaceMarker(tmpl, "//@FRAKTAL_HIT_RULE", std::string(kHitRuleDefines[int(f.hitRule)]));
    const size_t nodesAt = tmpl.find("//@FRAKTAL_NODES");
    if (nodesAt == std::string::npos) throw std::logic_error("formula.glsl lacks //@FRAKTAL_NODES");

    // Text before the marker keeps its own line numbers; the node functions follow: the first
    // fractal's, the objects', then each combined fractal's, numbered on.
    GlslEmitter e;
    e.out = tmpl.substr(0, nodesAt);
    const FractalNames first{fractalSuffix(0), 0};
    emitFractalNodes(e, f, first, "", g.nodeNames);
    const bool objects = emitObjects(e, f, int(f.nodes.size()) + 1, g.nodeNames);
    std::vector<FractalNames> combined;
    int line = int(f.nodes.size() + 1 + f.objects.size());
    for (size_t j = 0; j < f.fractals.size(); ++j) {
        const Formula& c = f.fractals[j].formula;
        combined.push_back({fractalSuffix(j + 1), line});
        line += int(c.nodes.size()) + 1;
        if (f.fractals[j].enabled)
            emitFractalNodes(e, c, combined.back(), "fractal " + std::to_string(j + 2) + ": ", g.nodeNames);
        else
            for (size_t k = 0; k <= c.nodes.size(); ++k) g.nodeNames.push_back("fractal " + std::to_string(j + 2));
    }
    e.restoreFormulaLines();
    e.out += fractalInstance(f, first, f.hitRule);
    for (size_t j = 0; j < f.fractals.size(); ++j)
        if (f.fractals[j].enabled) e.out += fractalInstance(f.fractals[j].formula, combined[j], f.hitRule);

    std::string rest = tmpl.substr(tmpl.find('\n', nodesAt) + 1);
    replaceMarker(rest, "//@FRAKTAL_COMBINE", combineFractals(f, objects));
    replaceMarker(rest, "//@FRAKTAL_MEMBERSHIP",
                  f.membershipIsFlag() ? "    return !escaped;" : "    return d <= 0.0;");
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
    // Each message's place (in any driver's form, parseShaderLog) becomes what the line numbers
    // encode (kFormulaLineBase, kNodeLineStride); lines in no known form stay as they are.
    std::string out;
    size_t from = 0;
    while (from < log.size()) {
        size_t end = log.find('\n', from);
        if (end == std::string_view::npos) end = log.size();
        const std::string_view text = log.substr(from, end - from);
        const std::vector<ShaderLogMessage> parsed = parseShaderLog(text);
        std::string where;
        if (!parsed.empty()) {
            const int line = parsed[0].line;
            if (line < kFormulaLineBase) {
                where = programName + " line " + std::to_string(line);
            } else if (line < kNodeLineStride) {
                where = "generated formula code line " + std::to_string(line - kFormulaLineBase);
            } else if (const size_t node = size_t(line / kNodeLineStride - 1); node < nodeNames.size()) {
                where = nodeNames[node] + ", GLSL line " + std::to_string(line % kNodeLineStride);
            }
        }
        if (where.empty())
            out += text;
        else
            out += where + ": " + parsed[0].text;
        if (end < log.size()) out += '\n';
        from = end + 1;
    }
    return out;
}

}  // namespace fraktal
