// A 2D formula: the same node-list model as core/formula.hpp over the plane state. `start` runs
// once (the Koch snowflake's fold into a side's frame), `nodes` every iteration, the estimator
// closes. CPU evaluation in double; shaders/plane_formula.glsl mirrors it.
#pragma once

#include <string>
#include <vector>

#include "core/formula.hpp"
#include "core/plane/plane_block.hpp"

namespace fraktal {

// Runs on the iterations its schedule says, as in 3D.
struct PlaneNode : IterationSchedule {
    const PlaneBlockDesc* block = nullptr;
    std::vector<ParamValue> values;  // one per block->params (floats in x), in declaration order
    bool enabled = true;

    static PlaneNode make(const PlaneBlockDesc& block);  // with default parameter values
    Args args() const { return Args{values.data()}; }
};

struct PlaneFormula {
    std::vector<PlaneNode> start;  // run once, before the loop
    std::vector<PlaneNode> nodes;  // the loop body
    PlaneNode estimator;
    int iterations = 100;
    double bailout = 2.0;  // |z| > bailout ends the orbit (escaped)

    // What needs a recompile (block ids, order, enable, schedule); values are uniforms.
    std::string structureKey() const;
    // Whole-number powers only: a non-whole power runs in float on the GPU (see Power).
    bool needsFloatPower() const;
};

struct PlaneEvaluation {
    double distance = 0.0;          // the estimator's distance (meaningful outside)
    int iterations = 0;             // iterations run before the orbit was decided (or all)
    double smoothIterations = 0.0;  // continuous count for escaped orbits (else = iterations)
    bool escaped = false;
    bool captured = false;
    bool inside = false;  // membership, per the estimator's PlaneMembership
};

inline bool planeInside(PlaneMembership m, bool escaped, bool captured, double distance) {
    switch (m) {
        case PlaneMembership::NotEscaped: return !escaped;
        case PlaneMembership::Region: return !escaped && distance <= 0.0;
        case PlaneMembership::Captured: return captured;
    }
    return false;
}

// Smooth (continuous) iteration count of an escaped orbit: n - log_p(log|z| / log B) (the
// normalised iteration count, Linas Vepstas "Renormalizing the Mandelbrot escape"); it ranges
// over [n-1, n) when the bailout B is large. Orbits that never passed the bailout keep n.
double planeSmoothIterations(int n, double absZ, double bailout, double power);

PlaneEvaluation evaluatePlane(const PlaneFormula& f, const real2& pos);

}  // namespace fraktal
