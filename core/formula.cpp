#include "core/formula.hpp"

#include <algorithm>
#include <stdexcept>

namespace fraktal {

std::string_view categoryName(Category c) {
    switch (c) {
        case Category::Fold: return "fold";
        case Category::Transform: return "transform";
        case Category::Power: return "power";
        case Category::Estimator: return "estimator";
    }
    return "?";
}

const BlockDesc* findBlock(std::string_view id) {
    for (const BlockDesc& b : allBlocks())
        if (b.id == id) return &b;
    return nullptr;
}

Node Node::make(const BlockDesc& block) {
    Node n;
    n.block = &block;
    for (const ParamDecl& p : block.params) n.values.push_back(p.defaultValue);
    return n;
}

vec3 FractalPlacement::localFromWorld(const vec3& world) const {
    return scale * (Placement::localFromWorld() * repeatCell(world - center, repeat));
}

std::string Formula::structureKey() const {
    std::string key;
    for (const Node& n : nodes) {
        key += std::string(n.block->id) + (n.enabled ? "" : "!") + "/" + n.key() + ";";
    }
    key += "=>" + std::string(estimator.block ? estimator.block->id : "");
    // An object's kind, operation, shell and whether it is on are compiled in; its placement and
    // parameters are uniforms.
    for (const SceneObject& o : objects)
        key += "+" + std::string(o.block->id) + ":" + std::string(kObjectOperationNames[int(o.operation)]) +
               (o.hollow ? ":hollow" : "") + (o.enabled ? "" : ":off");
    if (hitRule != HitRule::Surface) key += "|hit " + std::string(kHitRuleNames[int(hitRule)]);
    // A user's block is compiled from its text: editing its GLSL or its parameter list (same id)
    // is a change of structure. Built-in blocks are fixed by their id.
    auto addCustom = [&key](const BlockDesc* b) {
        if (!b || !b->custom) return;
        key += "|" + std::string(b->id) + (b->wholeDE ? "(whole DE)" : "") + "{";
        // The type too: a float and a vec3 parameter are different uniform declarations.
        for (const ParamDecl& p : b->params) key += std::string(p.name) + (p.type == ParamType::Vec3 ? ":v," : ":f,");
        key += "}" + std::string(b->glsl);
    };
    for (const Node& n : nodes) addCustom(n.block);
    addCustom(estimator.block);
    // A combined fractal's structure, operation and whether it is on are compiled in; its
    // placement, like the first one's, is uniforms.
    for (const CombinedFractal& c : fractals)
        key += "|&" + std::string(kObjectOperationNames[int(c.operation)]) + (c.enabled ? "" : ":off") + "(" +
               c.formula.structureKey() + ")";
    return key;
}

bool Formula::membershipIsFlag() const {
    return !fractals.empty() || estimator.block->membership == Membership::EscapeTime;
}

Formula Formula::fractalAlone(size_t index) const {
    Formula alone = fractalAt(index);
    alone.fractals.clear();
    alone.boundRadius = boundRadius;
    alone.hitRule = hitRule;
    alone.customBlocks = customBlocks;
    alone.objects = objects;
    return alone;
}

bool canBoundEscape(const std::vector<Node>& nodes) {
    for (const Node& n : nodes)
        if (n.enabled && (n.block->custom || n.block->category == Category::Power ||
                          n.block->category == Category::Fold || n.block->id == "scale"))
            return true;
    return false;
}

DerivativeBound derivativeBound(const std::vector<Node>& nodes) {
    DerivativeBound weakest = DerivativeBound::Global;
    for (const Node& n : nodes)
        if (n.enabled) weakest = std::max(weakest, n.block->derivativeAt(n.args()));
    return weakest;
}

int firstJumpingStep(const std::vector<Node>& nodes) {
    for (size_t k = 0; k < nodes.size(); ++k)
        if (jumps(nodes[k])) return int(k);
    return -1;
}

bool Formula::cpuEvaluable() const {
    for (const Node& n : nodes)
        if (n.block->custom) return false;
    for (const CombinedFractal& c : fractals)
        if (!c.formula.cpuEvaluable()) return false;
    return !estimator.block->custom;
}

namespace {

// One iteration of the node list: the body of the loops in shaders/formula.glsl.
void iterate(const Formula& f, P4& p, const vec3& c, int i) {
    p.iteration = i;
    for (const Node& n : f.nodes)
        if (n.enabled && n.runsOn(i)) {
            if (!n.block->apply) throw std::logic_error("a formula with custom GLSL blocks has no CPU evaluation");
            n.block->apply(p, c, n.args());
            if (n.block->raisesDegree()) p.degree *= n.block->degreeAt(n.args());
        }
}

// The estimator's orbit value at pos's orbit after exactly `count` iterations: log r for
// escape-time estimators, the estimate at w = 1 for distance ones (P4::orbitGradient).
double orbitValue(const Formula& f, const vec3& pos, int count) {
    P4 p{pos, 1.0};
    const vec3 c = pos;
    for (int i = 0; i < count; ++i) iterate(f, p, c, i);
    if (f.estimator.block->membership == Membership::EscapeTime)
        return std::log(max(length(vec4(p.xyz, p.pointW)), 1e-30));
    P4 unit{p.xyz, 1.0, p.degree};
    unit.pointW = p.pointW;
    return f.estimator.block->estimate(unit, c, f.estimator.args());
}

// |grad V| at pos by tetrahedral differences: for the vertices k of a regular tetrahedron,
// sum k (k . g) = 4 g.
double orbitValueGradient(const Formula& f, const vec3& pos, int count, double h) {
    const vec3 k0(1.0, -1.0, -1.0), k1(-1.0, -1.0, 1.0), k2(-1.0, 1.0, -1.0), k3(1.0, 1.0, 1.0);
    vec3 g = k0 * orbitValue(f, pos + h * k0, count) + k1 * orbitValue(f, pos + h * k1, count) +
             k2 * orbitValue(f, pos + h * k2, count) + k3 * orbitValue(f, pos + h * k3, count);
    return length(g) / (4.0 * h);
}

// One fractal at a point of its own frame, its placement aside: the orbit and the estimate
// times its DE factor, under the hit rule `rule`. Mirrors fractalEval() in
// shaders/formula_fractal.glsl: keep the two in step.
Evaluation evaluateFractal(const Formula& f, const vec3& pos, HitRule rule, double hitThreshold) {
    if (f.estimator.block->custom)
        throw std::logic_error("a formula with custom GLSL blocks has no CPU evaluation; use gl::DEProbe");
    Evaluation e;
    P4 p{pos, 1.0};
    const vec3 c = pos;
    const double bailout2 = f.bailout * f.bailout;
    const int iterations = std::clamp(f.iterations, 0, kMaxIterations);
    for (int i = 0; i < iterations; ++i) {
        iterate(f, p, c, i);
        e.trap.value = min(e.trap.value, vec4(abs(p.xyz), length(p.xyz)));
        e.iterations = i + 1;
        if (dot(p.xyz, p.xyz) + p.pointW * p.pointW > bailout2) {
            e.escaped = true;
            break;
        }
    }
    // The degrees of the iterations the orbit did not run, and of all of them, counted in log2 (a
    // count of runs per power node: no loop over the iterations, and no overflow).
    double remainingLog2 = 0.0, allLog2 = 0.0;
    for (const Node& n : f.nodes)
        if (n.enabled && n.block->raisesDegree()) {
            const double d = std::log2(n.block->degreeAt(n.args()));
            remainingLog2 += double(n.iterationsRunBefore(iterations) - n.iterationsRunBefore(e.iterations)) * d;
            allLog2 += double(n.iterationsRunBefore(iterations)) * d;
        }
    p.surfaceLogR = allLog2 > 0.0 ? std::log(f.bailout) * std::exp2(-remainingLog2) : 0.0;
    if (f.estimator.block->usesOrbitGradient()) {
        // The difference step: 0.02 of the estimate with the running derivative (the estimator
        // without the gradient), so that the orbit value is close to linear across it (the
        // tetrahedral stencil's error is first order in the step: 0.9% on the squaring ball at 0.02,
        // tests/de_quality_test.cpp), and no finer than single precision resolves at pos. 0 there
        // (inside, for escape-time estimates): no gradient.
        const double running = std::abs(f.estimator.block->estimate(p, c, f.estimator.args()));
        const double reach = 1.0 + length(pos);
        if (running > 0.0)
            p.orbitGradient =
                orbitValueGradient(f, pos, e.iterations, std::clamp(0.02 * running, 1e-5 * reach, 1e-2 * reach));
    }
    e.orbitGradient = p.orbitGradient;
    e.distance = f.estimator.block->estimate(p, c, f.estimator.args()) * f.deFactor;
    e.inside = isInside(*f.estimator.block, e.distance, e.escaped);
    if (rule == HitRule::InteriorWalls && hitThreshold > 0.0 && (e.inside || e.distance < 0.5 * hitThreshold))
        e.distance = hitThreshold;
    return e;
}

// A fractal at a world point: in its placed frame, the estimate back in world units (the
// threshold, a world length, taken into the frame and back).
Evaluation evaluatePlaced(const Formula& f, const vec3& world, HitRule rule, double hitThreshold) {
    if (f.placement.identity()) return evaluateFractal(f, world, rule, hitThreshold);
    const double scale = f.placement.scale;
    Evaluation e = evaluateFractal(f, f.placement.localFromWorld(world), rule, hitThreshold * std::abs(scale));
    e.distance /= scale;
    return e;
}

}  // namespace

// Mirrors formulaEval() in the generated GLSL (shaders/formula.glsl, core/glsl_gen.cpp): keep the
// two in step.
Evaluation evaluate(const Formula& f, const vec3& pos, double hitThreshold) {
    Evaluation e = evaluatePlaced(f, pos, f.hitRule, hitThreshold);
    for (const CombinedFractal& c : f.fractals) {
        if (!c.enabled) continue;
        const Evaluation o = evaluatePlaced(c.formula, pos, f.hitRule, hitThreshold);
        const bool inside = e.inside;
        bool taken = false;
        switch (c.operation) {
            case ObjectOperation::Join:
                taken = o.distance < e.distance;
                e.distance = std::min(e.distance, o.distance);
                e.inside = inside || o.inside;
                break;
            case ObjectOperation::Intersect:
                taken = o.distance > e.distance;
                e.distance = std::max(e.distance, o.distance);
                e.inside = inside && o.inside;
                break;
            case ObjectOperation::Carve: {
                // A distance estimator's estimate is signed; an escape-time one's is no distance
                // inside its set (why: evaluate() in core/formula.hpp).
                const double cut = c.formula.estimator.block->membership == Membership::EscapeTime && o.inside
                                       ? 1.5 * hitThreshold
                                       : -o.distance;
                taken = cut > e.distance;
                e.distance = std::max(e.distance, cut);
                e.inside = inside && !o.inside;
                break;
            }
        }
        if (taken) {
            const double distance = e.distance;
            const bool combinedInside = e.inside;
            e = o;
            e.distance = distance;
            e.inside = combinedInside;
        }
    }
    if (!f.fractals.empty()) e.escaped = !e.inside;
    if (!f.objects.empty())
        e.distance = combineObjects(f.objects, pos, e.distance, e.inside, f.membershipIsFlag(), e.surface);
    return e;
}

}  // namespace fraktal
