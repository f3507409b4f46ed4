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
        key += "|" + std::string(b->id) + "{";
        // The type too: a float and a vec3 parameter are different uniform declarations.
        for (const ParamDecl& p : b->params) key += std::string(p.name) + (p.type == ParamType::Vec3 ? ":v," : ":f,");
        key += "}" + std::string(b->glsl);
    };
    for (const Node& n : nodes) addCustom(n.block);
    addCustom(estimator.block);
    return key;
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
    return !estimator.block->custom;
}

namespace {

// One iteration of the node list: the body of the loops in shaders/formula.glsl.
void iterate(const Formula& f, P4& p, const vec3& c, int i) {
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
    if (f.estimator.block->membership == Membership::EscapeTime) return std::log(max(length(p.xyz), 1e-30));
    return f.estimator.block->estimate(P4{p.xyz, 1.0, p.degree}, c, f.estimator.args());
}

// |grad V| at pos by tetrahedral differences: for the vertices k of a regular tetrahedron,
// sum k (k . g) = 4 g.
double orbitValueGradient(const Formula& f, const vec3& pos, int count, double h) {
    const vec3 k0(1.0, -1.0, -1.0), k1(-1.0, -1.0, 1.0), k2(-1.0, 1.0, -1.0), k3(1.0, 1.0, 1.0);
    vec3 g = k0 * orbitValue(f, pos + h * k0, count) + k1 * orbitValue(f, pos + h * k1, count) +
             k2 * orbitValue(f, pos + h * k2, count) + k3 * orbitValue(f, pos + h * k3, count);
    return length(g) / (4.0 * h);
}

}  // namespace

// Mirrors formulaDE() in shaders/formula.glsl: keep the two in step.
Evaluation evaluate(const Formula& f, const vec3& pos, double interiorWallsThreshold) {
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
        if (dot(p.xyz, p.xyz) > bailout2) {
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
    if (f.hitRule == HitRule::InteriorWalls && interiorWallsThreshold > 0.0 &&
        (e.inside || e.distance < 0.5 * interiorWallsThreshold))
        e.distance = interiorWallsThreshold;
    if (!f.objects.empty())
        e.distance = combineObjects(f.objects, pos, e.distance, e.inside,
                                    f.estimator.block->membership == Membership::EscapeTime);
    return e;
}

}  // namespace fraktal
