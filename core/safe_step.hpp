// The closing estimator and the step factor that make a composed formula safe to march, found
// by measurement against the baseline marcher (core/de_check.hpp).
//
// Every block carries the running derivative w in p.w: similarity transforms and conformal
// folds multiply it by their scale (1 for rotations, translations, box and plane folds; |s| for
// scales; the fold factor for sphere folds and inversions), non-conformal deforms by their
// Jacobian's largest singular value (twist and bend: that of I + u v^T, |u| = |k| r), add_c adds
// |weight| (nothing in Julia mode). The spherical powers multiply it by their largest stretch,
// n r^(n-1) max(1, |sin(n theta + phase) / sin(theta)|) clamped to n (formulas/mandelbulb.hpp,
// formulas/mandelbulb_variants.hpp), the Bristorbrot by its Jacobian's largest singular value,
// the quaternion orbits by the analytic scalar 2 |q| (White/Nylander;
// Syntopia, "Distance estimated 3D fractals" part V). Each step block declares how far its factor
// bounds its stretch (DerivativeBound, core/block.hpp). The escape-time estimators divide by it:
// - log, 0.5 log(r) r / w: the Hubbard-Douady potential's lower bound, for power iterations
//   (Syntopia part V; Knighty's notes on fractalforums.com, "Mandelbulb distance estimation"),
//   with log r counted from the surface the iteration count draws (P4::surfaceLogR): the bound
//   is for the distance to the limit set, which lies inside that surface.
// - potential, the log form times (1 - e^-G) / G with G = log(r) / the product of the power
//   steps' degrees (P4::degree): equal to it near the object, where G is small, and not
//   outgrowing the distance far from it (for a power alone, half the distance to the ball it
//   draws at every r, where the log form runs from 0.5 to 0.82 of it at 2 from the unit ball), so
//   one step factor fits near and far samples.
// - linear, r / w: Syntopia part VI's Mandelbox form, for fold-and-scale stacks.
// - gradient twins (escape_gradient beside the escape-time estimates, box_gradient beside a box,
//   sphere_gradient and tetrahedron_gradient beside theirs):
//   the same estimate over |grad| of the composed map's orbit value, by tetrahedral differences of
//   the orbit, in place of w. w multiplies each step's largest stretch, and where the stretched
//   direction turns from step to step (twists, bends) that product outgrows the composed map's
//   stretch; the difference is no derivative across a fold or a jump. Five orbits an estimate:
//   their speed is weighed by it.
// The Lipschitz form (r - B) / w with B the bailout (Hart, Sandin and Kauffman, "Ray tracing
// deterministic 3-D fractals", 1989) never overshoots where w bounds the stretch, but it
// vanishes on every escape level set |F_k| = B, not only at the fractal: a marcher stops on those
// false shells, so it is not offered here.
// Neither escape-time estimate is a proven bound: the log form outgrows the distance far from the
// object, a non-integer power's map jumps where atan2 wraps, a phase sends a pole to a circle, and
// a bailout that a following fold undoes leaves a shell where the estimate is large and the
// object near. A primitive's distance over w is one only after Global steps. So the factor is
// measured on sampled rays and, where nothing proves it, a margin is kept for the rays that were
// not sampled: the wider where a step jumps, the narrower where the sampled rays' tail shows a
// ceiling.
#pragma once

#include <stop_token>
#include <string>
#include <vector>

#include "core/de_check.hpp"

namespace fraktal {

struct SafeStepOptions {
    // Rays are sampled in rounds of rays.rays (seeds rays.seed, rays.seed + 1, ...) until
    // `settledRounds` rounds in a row raise the worst DE / true distance of the formula's own
    // estimator by less than `settled`, or `maxRounds` rounds: a formula whose worst case is rare
    // (a jump, a pole) gets more rays than one whose every ray shows it.
    ConservativenessOptions rays{64, 2000, 1};
    int maxRounds = 8;
    int settledRounds = 2;
    double settled = 0.02;
    // Rounds go on, up to `tailRounds` in all, while the fixed margin below does not cover the
    // worst that the rays' tail projects (projectedWorst x margin > the sampled worst): a heavy
    // tail's worst rays are rare, and the few hundred rays that settle the worst miss them (the
    // Amazing Surf showed 1.48 at factor 1 on 95 hit rays, 1.97 on 2000 rays; the Kleinian 1.36
    // and 4.4). 0 or fewer than maxRounds: the settled rounds alone (the editor's quick
    // measurement after a structure change). Not for a proven bound, whose factor does not rest
    // on the margin.
    int tailRounds = 32;
    // Of the largest factor the sampled rays allow, for estimates that are approximations
    // (escape-time ones, and primitives after Local steps): rays that were not sampled may be
    // worse. tests/safe_step_test.cpp measures how often they are on random stacks.
    double margin = 0.8;
    // After a step that jumps (DerivativeBound::None: wraps, conditional shifts, non-integer
    // powers): the worst case sits at the jumps, which few rays pass close to. On 1000 random
    // stacks (five seeds of tests/safe_step_test.cpp) other rays showed up to 1.25x the worst
    // the rounds had seen after a jump (1.16x after Local steps), leaving aside a Kleinian step
    // wrapped outside its group (2.8x), which has no safe factor, and stacks whose factor is
    // held at kMaxStepFactor; 0.7 keeps 1.43x.
    double jumpMargin = 0.7;
    // Where the sampled rays' worst ratios crowd under a ceiling, the fixed margins above are
    // wider than the rays call for: the factor may then be `tailMargin` of the one for the worst
    // their tail projects over `raysAhead` rays (projectedWorst), when that is larger. On the
    // random stacks' escape-time estimates after 6 iterations the rays' worst ratios sit within
    // a few percent of the log estimate's 0.5; after 12 iterations (the shipped bulbs) they
    // spread, and the projection is more cautious than the margins.
    double raysAhead = 10000;
    double tailMargin = 0.95;
    // IFS primitive estimates (membership by distance) after Global steps only: the primitive's
    // distance over the running scale is a Lipschitz bound (tests/safe_step_test.cpp checks each
    // block's declaration), so factor 1 is safe whatever the rays show, up to rounding; a
    // larger factor, where the bound is loose, is measured like any estimate.
    double boundMargin = 0.99;
    // A gradient twin whose rays showed it above this many times the distance at factor 1 is not
    // offered. Where the differences straddle a fold or a jump the estimate is no distance, and
    // rays pass close to those places rarely: on random stacks (tests/safe_step_test.cpp, stacks
    // seed 22) a box_gradient the rounds saw at 110x overshot other rays 1.32x at the factor
    // they allowed, 0.007.
    double gradientWorst = 2.0;
    // Rounds end early once a stop is requested (the editor's further rounds, on a worker thread,
    // when the structure changes again): the rays sampled so far are measured.
    std::stop_token stop;

    bool proven(const BlockDesc& estimator, const std::vector<Node>& steps) const {
        return estimator.membership == Membership::Distance && !estimator.usesOrbitGradient() &&
               derivativeBound(steps) == DerivativeBound::Global;
    }
    // The margin kept below the factor the rays allow.
    double marginFor(const std::vector<Node>& steps) const {
        return derivativeBound(steps) == DerivativeBound::None ? jumpMargin : margin;
    }
    // The safe step factor for a stack whose rays showed `atUnit` (DE / true distance at factor
    // 1): the larger of the fixed margin's and the tail's (above; a proven bound's, below).
    double factorFor(const ConservativenessReport& atUnit, const BlockDesc& estimator,
                     const std::vector<Node>& steps) const;
    double factorFor(const ConservativenessReport& atUnit, const Formula& f) const {
        return factorFor(atUnit, *f.estimator.block, f.nodes);
    }
    // Whether rays that showed `atUnit` need no further rounds for the tail (tailRounds): the
    // bound is proven, whose factor does not rest on the margin, or the fixed margin covers the
    // worst the tail projects. Where it holds when the settled rounds end, the further rounds
    // end there as well, and on the same rays the two measurements agree.
    bool tailCovered(const ConservativenessReport& atUnit, const BlockDesc& estimator,
                     const std::vector<Node>& steps) const;
    // Whether either of those factors is at least kMinStepFactor.
    bool hasFactor(const ConservativenessReport& atUnit, const std::vector<Node>& steps) const;
};

// The worst DE / true distance expected over `rays` rays, projected from the tail of the sampled
// rays' worst ratios (report.rayWorst): each ray is an independent draw, and the largest few
// tell how fast the ratio grows with more rays. For the k largest, Hill's estimate of the tail
// index, gamma = mean of log(Y_i / Y_k+1) over i <= k (B. M. Hill, "A simple general approach to
// inference about the tail of a distribution", Ann. Statist. 3(5), 1975), extrapolated as
// Weissman's quantile Y_k+1 (k rays / (n p))^gamma with p = 1 / rays (I. Weissman, "Estimation
// of parameters and large quantiles based on the k largest observations", JASA 73, 1978). An
// estimate with a ceiling (the escape-time ones near the surface, a primitive's bound) has its
// top rays close together and gamma near 0; a heavy tail (a Kleinian group wrapped outside
// itself, a jump) spreads them. The largest projection over k from 2 to a fifth of the rays (at
// least 5, at most 100) is taken: small k sees one ray far above the rest (a rare overshoot among
// rays at a ceiling), large k a tail that is heavy throughout. Never below the sampled worst;
// twice the sampled worst where fewer than 7 rays were measured or the k+1-th largest is 0. A
// power law fitted to a tail that ends at a ceiling overshoots the ceiling: the projection is
// cautious there, never bold (tests/safe_step_test.cpp measures both on drawn tails).
double projectedWorst(const ConservativenessReport& report, double rays);

// The report as if the formula's deFactor were 1 (a sampler applies its formula's own).
ConservativenessReport atUnitFactor(ConservativenessReport report, double deFactor);

// The range of formula.deFactor a preset may hold.
inline constexpr double kMinStepFactor = 1e-3;
inline constexpr double kMaxStepFactor = 2.0;

// The rays the safe step is measured on, in rounds as SafeStepOptions says, with the report of
// the sampler's own estimate on them (the rounds evaluate it to decide when to stop).
struct SafeStepRays {
    RaySamples samples;
    ConservativenessReport report;  // at the sampler's formula's own deFactor
};
SafeStepRays sampleSafeStepRays(FormulaSampler& sampler, const Camera& camera, const SafeStepOptions& options = {});

// margin / worstRatio, clamped to the preset's range and rounded down to 3 decimals.
double safeStepFactor(double worstRatio, double margin);
// Whether margin / worstRatio is finite and at least kMinStepFactor: a stack whose estimate
// overshoots by more (dust, jumps into a neighbour's cell) has no safe factor a preset may hold.
bool hasSafeStepFactor(double worstRatio, double margin);

struct EstimatorMeasurement {
    Node estimator;                 // the closing block measured
    ConservativenessReport report;  // at step factor 1
    double projectedWorst = 0.0;    // projectedWorst(report, SafeStepOptions::raysAhead)
    double factor = 1.0;            // the safe step factor for it
    bool hasFactor = true;          // SafeStepOptions::hasFactor
    // The safe factor times the median ratio, the share of the gap a typical march step covers,
    // per orbit an estimate runs (the gradient estimate runs five). A proxy only: it cannot see
    // an estimate that vanishes away from the surface (false hits look fast), so a choice is
    // confirmed by rendering and by the DE count.
    double speed() const { return factor * report.medianRatio / estimator.block->orbitsPerEstimate(); }
};

// hasSafeStepFactor for a measured estimator (true when no ray reached the object: nothing was
// measured against).
inline bool hasSafeStepFactor(const EstimatorMeasurement& m) { return m.report.samples == 0 || m.hasFactor; }

// The formula's own estimator, measured.
EstimatorMeasurement measureSafeStep(FormulaSampler& sampler, const Camera& camera,
                                     const SafeStepOptions& options = {});
EstimatorMeasurement measureSafeStep(const Formula& f, const Camera& camera, const SafeStepOptions& options = {});
// The same on rays already sampled for f (sampleSafeStepRays with a sampler of f).
EstimatorMeasurement measureSafeStep(const Formula& f, const SafeStepRays& rays, const SafeStepOptions& options);

// The linear estimator r / w.
Node linearEstimator();

// The tag of a formula's structure that Formula::deFactorMeasuredFor holds once its factor was
// measured: 16 hex digits of the FNV-1a hash of Formula::structureKey (stable across runs and
// machines, unlike std::hash).
std::string stepFactorTag(const Formula& f);
// Whether f's factor was measured for the structure it has now.
inline bool stepFactorMeasured(const Formula& f) { return f.deFactorMeasuredFor == stepFactorTag(f); }

// The formula's own estimator and, for escape-time formulas, linear r / w, log and potential, then
// the gradient twins of those measured (a primitive's too; none after a step that jumps), each
// measured on the same rays (they share the membership, so the object is the same); best first
// (the largest speed()). A custom estimator has no twin: it is measured alone.
// Needs a CPU-evaluable formula.
std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const Camera& camera,
                                                    const SafeStepOptions& options = {});
// The same on rays already sampled for f (sampleSafeStepRays with a CPU sampler of f), whose
// report is f's own estimate.
std::vector<EstimatorMeasurement> compareEstimators(const Formula& f, const SafeStepRays& rays,
                                                    const SafeStepOptions& options);

// f with the best estimator of compareEstimators and its safe step factor applied.
Formula withSafeEstimator(const Formula& f, const Camera& camera, const SafeStepOptions& options = {});

}  // namespace fraktal
