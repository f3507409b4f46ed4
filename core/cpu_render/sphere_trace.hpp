// The one CPU sphere tracer. Every march of a ray on the CPU runs this loop: the camera rays of
// the still, the viewport's CPU mirror and the path tracer (cpu_shading's marchRay, the mirror of
// shaders/march.glsl's marchSteps), the path tracer's shadow and bounce rays (the mirror of
// pathtrace.frag's traceSecondary), the editor's pick on a formula without a CPU body, and the
// formula fit's surface probe. What differs between them is a MarchRule (where a hit is, how far a
// step may go, what a step that lands inside does) and the distance source, never the loop.
//
// Not marched here: the soft shadow's penumbra march (it steps a minimum length and keeps the
// smallest d / t instead of stopping at a hit) and de_check's baseline march (a fixed-step
// reference with membership that judges the estimate, so it must not use it).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "core/formula.hpp"

namespace fraktal::cpu {

enum class MarchStatus { Marching, Hit, Escaped };

// The least and the largest steepest fall a ray keeps (march.glsl's STEEPEST_FLOOR and its
// quantizedSteepest's clamp): powers of two, exact in half precision.
inline constexpr double kSteepestFloor = 1.0 / 8192.0, kSteepestCeiling = 8192.0;

struct MarchState {
    double t = 0.0, lastD = 0.0, omega = 1.0;
    MarchStatus status = MarchStatus::Marching;
    int steps = 0;
    double closest = 1e30;  // the smallest d / t of the points passed (not the hit), as in shaders/march.glsl
    double steepest = kSteepestFloor;  // the steepest fall of the estimate per unit of ray met (march.glsl's)
    // The length of the last step taken: omega * lastD unless the rule's maxStep capped it (march.glsl
    // has no cap, and reads omega * lastD).
    double lastStep = 0.0;
};

// Where a march stops and how it steps.
struct MarchRule {
    // The hit threshold at distance t: epsilon + coneAngle * t. Camera rays stop within the pixel
    // footprint (coneAngle = pixelAngle * detail); secondary rays and probes at a fixed epsilon.
    double coneAngle = 0.0;
    double epsilon = 0.0;
    // The longest step. Far outside, escape-time estimates overshoot (few iterations run), so a probe
    // that starts far out caps its steps; camera rays start at the bound and need no cap.
    double maxStep = std::numeric_limits<double>::infinity();
    HitRule hitRule = HitRule::Surface;
    // A step that lands inside (by the source's membership) is bisected back to the crossing
    // (march.glsl's recoverOvershoot). Off for sources without membership.
    bool recoverOvershoot = false;
    // The largest omega the adaptive step may reach (march.glsl's u_maxStepGrowth); 1: omega never
    // grows past its start (MarchState::omega, 1 unless the caller over-relaxes).
    double maxStepGrowth = 1.0;

    double threshold(double t) const { return epsilon + coneAngle * t; }
};

// A distance source's answer at a point: the estimate and, where the source knows it, membership.
struct DistanceSample {
    double distance = 0.0;
    bool inside = false;
};

// Mirrors of march.glsl's adaptive step (why: there): how much the estimate fell per unit of ray
// over a step of lastStep from lastD to d, omega for the step after one of omega where the steepest
// fall met is `steepest`, and whether a step is taken back.
inline constexpr double kStepTargetFall = 0.5;
inline constexpr double kStepBackFall = 0.75;
inline constexpr double kStepGrowthPerStep = 2.0;
inline constexpr double kVerifiedMargin = 0.95;

inline double estimateFall(double lastStep, double lastD, double d) { return (lastD - d) / lastStep; }

inline double quantizedOmega(double omega) { return std::floor(omega * 32.0) / 32.0; }

inline double quantizedSteepest(double x) {
    int e = 0;
    const double m = std::frexp(std::clamp(x, kSteepestFloor, kSteepestCeiling), &e);
    return std::ldexp(std::ceil(m * 16.0) / 16.0, e);
}

inline double nextOmega(double omega, double steepest, double d, double threshold, double maxStepGrowth) {
    double limit = std::min(kVerifiedMargin * (2.0 - threshold / d) / (1.0 + steepest), maxStepGrowth);
    if (maxStepGrowth > 2.0) limit = std::max(limit, std::min(kStepTargetFall / steepest, maxStepGrowth));
    return quantizedOmega(std::clamp(std::min(omega * kStepGrowthPerStep, limit), 1.0, std::max(maxStepGrowth, 1.0)));
}

inline bool stepTakenBack(double omega, double lastD, double d, double threshold) {
    if (omega <= 1.0) return false;
    return omega < 2.0 ? d + lastD < omega * lastD + threshold : d < lastD * (1.0 - kStepBackFall);
}

// Mirror of march.glsl's recoverOvershoot (why: there). [tOut, tIn]: tOut outside with estimate
// dOut, tIn inside; bisected on membership to within the hit threshold at tOut.
template <class Source>
void recoverOvershoot(const Source& at, const vec3& ro, const vec3& rd, const MarchRule& rule, double tOut, double dOut,
                      double tIn, MarchState& s, double& deEvals) {
    constexpr int kRecoverBisections = 12;
    for (int i = 0; i < kRecoverBisections && tIn - tOut > rule.threshold(tOut); ++i) {
        const double tMid = 0.5 * (tOut + tIn);
        const DistanceSample e = at(ro + rd * tMid, 0.0);
        deEvals += 1.0;
        s.steps += 1;
        if (e.inside) {
            tIn = tMid;
        } else {
            tOut = tMid;
            dOut = e.distance;
        }
    }
    s.t = tOut;
    s.lastD = std::min(dOut, tIn - tOut);
    s.status = MarchStatus::Hit;
}

// Marches `s` on for up to maxSteps evaluations of `at` (DistanceSample at(const vec3& p, double
// threshold): the source is told the hit threshold at p, as evaluate() in core/formula.hpp takes
// it) from ro along unit rd, until a hit or t > tEnd. Resumable: a caller may march a few steps at a
// time with the same state. A source that returns a non-finite estimate escapes the ray (it would
// carry t to NaN and spend every remaining step).
template <class Source>
void marchSteps(const Source& at, const vec3& ro, const vec3& rd, double tEnd, const MarchRule& rule, int maxSteps,
                MarchState& s, double& deEvals) {
    for (int i = 0; i < maxSteps && s.status == MarchStatus::Marching; ++i) {
        // Mirror of march.glsl's marchSteps: past tEnd nothing counts, not even a hit.
        if (s.t > tEnd) {
            s.status = MarchStatus::Escaped;
            break;
        }
        const double threshold = rule.threshold(s.t);
        const DistanceSample e = at(ro + rd * s.t, threshold);
        deEvals += 1.0;
        s.steps += 1;
        double d = e.distance;
        if (!std::isfinite(d)) {
            s.status = MarchStatus::Escaped;
            break;
        }
        if (rule.hitRule == HitRule::InteriorWalls) {
            // Mirror of march.glsl's marchSteps for FRAKTAL_HIT_INTERIOR_WALLS (why: there).
            if (d < threshold || d <= 0.0) {
                s.lastD = std::max(d, 0.0);
                s.status = MarchStatus::Hit;
                break;
            }
            s.lastD = d;
            s.closest = std::min(s.closest, d / std::max(s.t, 1e-20));
            s.lastStep = d - 0.8 * threshold;
            s.t += s.lastStep;
            continue;
        }
        // Mirror of march.glsl's marchSteps (why: there).
        if (rule.hitRule == HitRule::InsideOnly) d = e.inside ? 0.0 : std::max(d, 1.01 * threshold);
        const double previousStep = s.lastStep;
        if (s.lastD > 0.0)
            s.steepest = quantizedSteepest(std::max(s.steepest, estimateFall(previousStep, s.lastD, std::abs(d))));
        if (s.lastD > 0.0 && stepTakenBack(s.omega, s.lastD, std::abs(d), threshold)) {
            s.t -= previousStep - s.lastD;
            s.lastStep = s.lastD;
            s.omega = 1.0;
            continue;
        }
        if (rule.recoverOvershoot && e.inside && s.lastD > 0.0) {
            recoverOvershoot(at, ro, rd, rule, s.t - previousStep, s.lastD, s.t, s, deEvals);
            if (s.t > tEnd) s.status = MarchStatus::Escaped;  // the crossing lies past the end
            break;
        }
        if (d <= threshold) {
            s.lastD = d;
            s.status = MarchStatus::Hit;
            break;
        }
        if (s.lastD > 0.0) s.omega = nextOmega(s.omega, s.steepest, std::abs(d), threshold, rule.maxStepGrowth);
        s.lastD = std::abs(d);
        s.closest = std::min(s.closest, s.lastD / std::max(s.t, 1e-20));
        s.lastStep = std::min(s.omega * d, rule.maxStep);
        s.t += s.lastStep;
    }
}

// A plain march of `at` over [tStart, tEnd] with `rule` (no over-relaxation): the distance of the
// hit, or none when the ray escapes or runs out of steps.
template <class Source>
std::optional<double> traceFirstHit(const Source& at, const vec3& ro, const vec3& rd, double tStart, double tEnd,
                                    const MarchRule& rule, int maxSteps, double& deEvals) {
    MarchState s;
    s.t = tStart;
    marchSteps(at, ro, rd, tEnd, rule, maxSteps, s, deEvals);
    // A hit refined past tEnd (past a shadow ray's light) is none.
    if (s.status != MarchStatus::Hit || s.t > tEnd) return std::nullopt;
    return s.t;
}

}  // namespace fraktal::cpu
