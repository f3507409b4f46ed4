// A formula: an ordered node list of blocks, run for N iterations with a bailout, closed by an
// estimator. This file holds the data and the CPU (double precision) evaluation.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/block.hpp"
#include "core/custom_block.hpp"
#include "core/iteration_schedule.hpp"
#include "core/scene_object.hpp"

namespace fraktal {

// The schedule says on which iterations the node runs: i % period == phase within [start, stop).
// This is how hybrids alternate formulas (Mandelbox on even and Mandelbulb on odd iterations) and
// how a block runs on the first iterations only.
struct Node : IterationSchedule {
    const BlockDesc* block = nullptr;
    std::vector<ParamValue> values;  // one per block->params, in declaration order
    bool enabled = true;

    static Node make(const BlockDesc& block);  // with default parameter values
    Args args() const { return Args{values.data()}; }
};

// Limits that keep any formula bounded (no preset can hang the machine); kMaxIterations is in
// core/iteration_schedule.hpp.
inline constexpr int kMaxNodes = 64;

// Where a marched ray stops.
enum class HitRule {
    // Where the estimate falls under the hit threshold (a pixel's footprint).
    Surface,
    // Only where the point is inside by the estimator's membership (an escape-time orbit that stays
    // bounded for all iterations, a distance estimate <= 0), the step crossing into it bisected back
    // to the threshold; the estimate only sizes the steps, never less than the threshold.
    // Mandelbulber2's iteration_threshold_mode (render_worker.cpp, calculate_distance.cpp): around
    // spiky sets (hypercomplex, power-2 bulbs) the log estimate falls under the threshold far from
    // the set, and this surface is the one its artists framed.
    InsideOnly,
    // Only in the band [0.5, 1] x threshold outside the set: a ray inside the set (by membership,
    // or an estimate under half the threshold) never stops there but crawls on a fifth of the
    // threshold at a time, and stops where it comes out. A camera or a cut (an intersected object)
    // inside the set sees the walls of its inner cavities. Mandelbulber2's interior_mode
    // (calculate_distance.cpp; RayMarching in render_worker.cpp steps to 0.8 x threshold).
    InteriorWalls,
};
inline constexpr std::string_view kHitRuleNames[] = {"surface", "insideOnly", "interiorWalls"};

// Where a fractal sits in the scene (Mandelbulber2's boolean mode, calculate_distance.cpp): the
// point is moved by -center, repeated in cells `repeat` wide about the origin (per axis; 0 does
// not repeat), turned into the fractal's frame and multiplied by `scale`; the estimate is divided
// by `scale`, so that it stays in world units. The identity by default.
struct FractalPlacement : Placement {
    double scale = 1.0;
    vec3 repeat{0.0};

    bool identity() const { return center == vec3(0.0) && !turned() && scale == 1.0 && repeat == vec3(0.0); }
    // The point in the fractal's own frame.
    vec3 localFromWorld(const vec3& world) const;
};

// At most this many fractals combined with the first (Mandelbulber2 has 9 slots).
inline constexpr int kMaxCombinedFractals = 8;

struct CombinedFractal;

struct Formula {
    // The loop body, in order; then the closing estimator.
    std::vector<Node> nodes;
    Node estimator;
    int iterations = 12;
    double bailout = 4.0;
    // The fractal lies inside this sphere about the origin. Marchers clip rays to it, and the
    // DE is only trusted inside it (escape-time estimates overshoot far away).
    double boundRadius = 4.0;
    // Multiplies the estimate: below 1 makes an overshooting hybrid safe (`fraktal check`).
    double deFactor = 1.0;
    // The structure deFactor was settled for (stepFactorTag in core/safe_step.hpp): written by
    // whatever measured it (the editor, `fraktal check --apply`, the import), and kept when the
    // artist then sets the factor by hand in the editor. Empty or another structure's: never
    // measured for this one, and the editor measures it when the file opens.
    std::string deFactorMeasuredFor;
    // Where a ray stops (HitRule).
    HitRule hitRule = HitRule::Surface;
    // Where the fractal sits (the identity unless it is placed among others).
    FractalPlacement placement;
    // Whole fractals combined with this one in order, before the objects (Mandelbulber2's boolean
    // mode): each joined with what comes before, intersecting it or carved from it, with its own
    // nodes, iterations, bailout, DE factor and placement. Membership is then the same boolean
    // combination of each fractal's own membership.
    std::vector<CombinedFractal> fractals;
    // Objects beside the fractal, combined in order with the estimate after it (each joined with
    // it, intersecting it or carved from it): Mandelbulber2's primitives and limit box. Their
    // distances are exact, so the DE factor does not scale them.
    std::vector<SceneObject> objects;
    // Keeps the user's GLSL blocks that nodes point to alive (shared, so copies stay valid).
    CustomBlocks customBlocks;

    // False when a node is a custom GLSL block: evaluate it with gl::DEProbe instead.
    bool cpuEvaluable() const;
    // Whether membership is a flag carried with the estimate (escape-time estimators, and any
    // combination of fractals) rather than the sign of the estimate.
    bool membershipIsFlag() const;
    // Fractal `index` alone: 0 is this one, without the fractals combined with it; 1.. the
    // combined ones, in order. Iterations, bailout, nodes and placement are its own; the bound,
    // hit rule, custom blocks and objects this formula's.
    Formula fractalAlone(size_t index) const;
    // Fractal `index`: 0 is this one, 1.. the combined ones.
    const Formula& fractalAt(size_t index) const;

    // Structure: what needs a recompile when it changes (block ids, order, enable, schedule). Parameter values,
    // iterations, bailout, bound and factor are uniforms.
    std::string structureKey() const;
};

// A fractal combined with the one before it (Formula::fractals). Its formula's own `fractals`
// and `objects` stay empty: they belong to the formula that holds it.
struct CombinedFractal {
    Formula formula;
    ObjectOperation operation = ObjectOperation::Join;
    bool enabled = true;
};

inline const Formula& Formula::fractalAt(size_t index) const {
    return index == 0 ? *this : fractals.at(index - 1).formula;
}

// The seed's colouring: minimum distances of the orbit to the three coordinate planes (xyz) and
// to the origin (w), accumulated after every iteration (seed 3.3).
struct OrbitTrap {
    vec4 value{1e20};
};

// Of a formula with combined fractals, the fields but `distance` and `inside` are those of the
// fractal that set the distance.
struct Evaluation {
    double distance = 0.0;
    OrbitTrap trap;
    int iterations = 0;          // iterations run before escape (or all of them)
    bool escaped = false;        // the orbit passed the bailout
    bool inside = false;         // membership, per the estimator's Membership rule and the objects
    double orbitGradient = 0.0;  // P4::orbitGradient, for estimators that read it (else 0)
    // The surface the distance is of: kFractalSurface (the fractals, coloured by the trap) or the
    // index of an object beside them (coloured by its own colour).
    int surface = kFractalSurface;
};

// Membership by the estimator's rule: escape-time formulas are inside where the orbit stayed
// bounded; IFS-type ones where the estimate is <= 0.
inline bool isInside(const BlockDesc& estimator, double distance, bool escaped) {
    return estimator.membership == Membership::EscapeTime ? !escaped : distance <= 0.0;
}

// Whether some enabled power, fold or scale block (or a custom one) can push orbits away: an
// escape-time estimator bounds no object without one (translations and rotations alone keep
// every orbit bounded, or none).
bool canBoundEscape(const std::vector<Node>& nodes);

// The weakest DerivativeBound of the enabled steps (Global for none): whether the estimator's
// distance over p.w is a proven bound.
DerivativeBound derivativeBound(const std::vector<Node>& nodes);
// Whether the node is an enabled step whose map jumps (DerivativeBound::None): a step factor can
// only be measured on sampled rays, and rare rays near the jump may overshoot more.
inline bool jumps(const Node& n) { return n.enabled && n.block->derivativeAt(n.args()) == DerivativeBound::None; }
// The index of the first step that jumps, or -1.
int firstJumpingStep(const std::vector<Node>& nodes);

// Throws std::logic_error for a formula that is not cpuEvaluable().
// hitThreshold: the hit threshold at pos while a ray is marched (0 elsewhere). With
// HitRule::InteriorWalls the set's inside, and its outside within half of it, then count as that
// threshold, before the objects (Mandelbulber2 applies its interior mode to the fractal alone).
// Inside an escape-time fractal that carves (CombinedFractal), whose estimate says nothing of the
// distance to its outside, the carved space counts as 1.5 thresholds: a marched ray crawls
// through it, as in Mandelbulber2's boolean SUB (calculate_distance.cpp).
Evaluation evaluate(const Formula& f, const vec3& pos, double hitThreshold = 0.0);
inline double distanceEstimate(const Formula& f, const vec3& pos) { return evaluate(f, pos).distance; }

}  // namespace fraktal
