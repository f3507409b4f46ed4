// The closing estimator and the step factor that make a composed formula safe to march, found
// by measurement against the baseline marcher (core/de_check.hpp).
//
// Every block carries the running derivative w in p.w: similarity transforms and conformal
// folds multiply it by their scale (1 for rotations, translations, box and plane folds; |s| for
// scales; the fold factor for sphere folds and inversions), non-conformal deforms by a bound of
// their Lipschitz constant (twist and bend: 1 + |k| r), add_c adds |weight| (nothing in Julia
// mode). The Mandelbulb power multiplies it by its largest stretch,
// n r^(n-1) max(1, |sin(n theta) / sin(theta)|) (formulas/mandelbulb.hpp); the other power blocks
// by the analytic scalar n r^(n-1) (White/Nylander; Syntopia, "Distance estimated 3D fractals"
// part V). The escape-time estimators divide by it:
// - log, 0.5 log(r) r / w: the Hubbard-Douady potential's lower bound, for power iterations
//   (Syntopia part V; Knighty's notes on fractalforums.com, "Mandelbulb distance estimation").
// - linear, r / w: Syntopia part VI's Mandelbox form, for fold-and-scale stacks.
// The Lipschitz form (r - B) / w with B the bailout (Hart, Sandin and Kauffman, "Ray tracing
// deterministic 3-D fractals", 1989) never overshoots where w bounds the stretch, but it
// vanishes on every escape level set |F_k| = B, not only at the fractal: a marcher stops on those
// false shells, so it is not offered here.
// Neither estimate is a proven bound for every stack: the scalar derivative of the other power
// blocks underestimates their Jacobian near the poles (the phi direction stretches by up to n
// times more), a non-integer power's map jumps where atan2 wraps, the log form outgrows the
// distance far from the object, and a bailout that a following fold undoes leaves a shell where
// the estimate is large and the object near. So the factor is measured on sampled rays and a
// margin is kept for the rays that were not sampled.
#pragma once

#include <string>
#include <vector>

#include "core/de_check.hpp"

namespace fraktal {

struct SafeStepOptions {
    ConservativenessOptions rays{48, 2000, 1};
    // Of the largest factor the sampled rays allow, for escape-time estimates (approximations:
    // rays that were not sampled may be worse).
    double margin = 0.6;
    // The same for IFS primitive estimates (membership by distance): the primitive's distance
    // over the running scale is a Lipschitz bound when every block's factor bounds its stretch
    // (tests/safe_step_test.cpp checks each block), so only rounding is left.
    double boundMargin = 0.99;
    double marginFor(const Node& estimator) const {
        return estimator.block->membership == Membership::Distance ? boundMargin : margin;
    }
};

// The range of formula.deFactor a preset may hold.
inline constexpr double kMinStepFactor = 1e-3;
inline constexpr double kMaxStepFactor = 2.0;

// margin / worstRatio, clamped to the preset's range and rounded down to 3 decimals.
double safeStepFactor(double worstRatio, double margin);

struct EstimatorMeasurement {
    Node estimator;                 // the closing block measured
    ConservativenessReport report;  // at step factor 1
    double factor = 1.0;            // the safe step factor for it
    // The safe factor times the median ratio: the share of the gap a typical march step covers.
    // A proxy only: it cannot see an estimate that vanishes away from the surface (false hits
    // look fast), so a choice is confirmed by rendering and by the DE count.
    double speed() const { return factor * report.medianRatio; }
};

// The formula's own estimator, measured.
EstimatorMeasurement measureSafeStep(FormulaSampler& sampler, const Camera& camera,
                                     const SafeStepOptions& options = {});
EstimatorMeasurement measureSafeStep(const Formula& f, const Camera& camera, const SafeStepOptions& options = {});

// The linear estimator r / w.
Node linearEstimator();

// Escape-time formulas: the formula's own estimator, linear r / w and log, each measured on
// the same rays (they share the membership, so the object is the same); best first (the largest
// speed()). Other formulas (IFS primitives, custom estimators): their own estimator alone.
// Needs a CPU-evaluable formula.
std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const Camera& camera,
                                                    const SafeStepOptions& options = {});
// The same on rays already sampled (sampleRays of f, at any deFactor).
std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const RaySamples& samples,
                                                    const SafeStepOptions& options);

// f with the best estimator of compareEstimators and its safe step factor applied.
Formula withSafeEstimator(const Formula& f, const Camera& camera, const SafeStepOptions& options = {});

}  // namespace fraktal
