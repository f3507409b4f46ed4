#include "core/plane/plane_formula.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal {

PlaneNode PlaneNode::make(const PlaneBlockDesc& block) {
    PlaneNode n;
    n.block = &block;
    for (const ParamDecl& p : block.params) n.values.push_back(p.defaultValue);
    return n;
}

std::string PlaneFormula::structureKey() const {
    std::string key = "plane:";
    auto add = [&key](const PlaneNode& n) {
        key += std::string(n.block->id) + (n.enabled ? "" : "!") + "/" + n.key() + ";";
    };
    for (const PlaneNode& n : start) add(n);
    key += "|";
    for (const PlaneNode& n : nodes) add(n);
    return key + "=>" + std::string(estimator.block ? estimator.block->id : "");
}

bool PlaneFormula::needsFloatPower() const {
    auto nonWhole = [](const PlaneNode& n) {
        const int at = n.block->paramIndex("power");
        return n.enabled && n.block->category == Category::Power && at >= 0 &&
               n.values[size_t(at)].x != std::round(n.values[size_t(at)].x);
    };
    return std::any_of(start.begin(), start.end(), nonWhole) || std::any_of(nodes.begin(), nodes.end(), nonWhole);
}

double planeSmoothIterations(int n, double absZ, double bailout, double power) {
    if (power <= 1.0 || absZ <= 1.0 || bailout <= 1.0) return double(n);
    return double(n) - std::log(std::log(absZ) / std::log(bailout)) / std::log(power);
}

// Mirrors planeEval() in shaders/plane_formula.glsl: keep the two in step.
PlaneEvaluation evaluatePlane(const PlaneFormula& f, const real2& pos) {
    PlaneEvaluation e;
    PlaneState s;
    s.z = pos;
    const real2 c = pos;
    for (const PlaneNode& n : f.start)
        if (n.enabled) n.block->apply(s, c, n.args());
    const double bailout2 = f.bailout * f.bailout;
    const int iterations = std::clamp(f.iterations, 0, kMaxIterations);
    bool passedBailout = false;
    if (!s.escaped && !s.captured) {
        for (int i = 0; i < iterations; ++i) {
            for (const PlaneNode& n : f.nodes)
                if (n.enabled && n.runsOn(i)) n.block->apply(s, c, n.args());
            e.iterations = i + 1;
            if (s.escaped || s.captured) break;
            if (glm::dot(s.z, s.z) > bailout2) {
                s.escaped = passedBailout = true;
                break;
            }
        }
    }
    e.escaped = s.escaped;
    e.captured = s.captured;
    e.smoothIterations = passedBailout ? planeSmoothIterations(e.iterations, glm::length(s.z), f.bailout, s.power)
                                       : double(e.iterations);
    e.distance = f.estimator.block->estimate(s, c, f.estimator.args());
    e.inside = planeInside(f.estimator.block->membership, e.escaped, e.captured, e.distance);
    return e;
}

}  // namespace fraktal
