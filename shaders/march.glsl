// shaders/march.glsl — needs DE() from the formula (shaders/formula.glsl, which also declares
// u_boundRadius).
//
// Sphere tracing with an adaptive step (below): over-relaxation (Keinert et al. 2014, "Enhanced
// Sphere Tracing", section 3.1) whose omega each ray grows and shrinks from its own estimates,
// with Keinert's fallback to the plain step from the previous point. Hit when
// d < pixelAngle * t * u_detail (the detail level tied to the pixel footprint: a bigger image has a
// smaller pixelAngle and so resolves finer detail); escaped when t > tEnd. deEvals counts DE calls.
//
// The state is resumable: a viewport may call marchRay a few steps per frame with the same state.
// Start a ray with marchStart(tStart). A ray that is still MARCH_MARCHING after its step budget has
// usually crawled along a grazing surface; callers decide (the still renderer treats it as a hit
// when the last distance is within a few footprints).
//
// Uniforms (set from RenderSettings by core/render/shading_uniforms.cpp):
//   float u_detail          hit threshold in pixel footprints (1 = one pixel; 0.5 = half a pixel)
//   float u_overRelaxation  initial omega of over-relaxed sphere tracing, in [1, 2) (1 = plain)
//   float u_maxStepGrowth   the largest omega the adaptive step may reach, at least u_overRelaxation
uniform float u_detail;
uniform float u_overRelaxation;
uniform float u_maxStepGrowth;
uniform float u_viewDistance;  // camera rays end this far from the camera (0: no limit)

// The adaptive step. The step factor (DE()'s deFactor) is measured once for the whole scene, so it
// is set by the worst rays, where the estimate exceeds the distance most; elsewhere the estimate
// is often a small share of the distance (the check's DE / true distance: 2-3 % at the median on
// Kleinian and random stacks), and a ray that steps omega = 1 times it crawls. Each ray therefore
// sizes its steps from what its own estimates do: `steepest` is the fastest the estimate has
// fallen per unit of ray along it (a lower bound of the field's local Lipschitz constant, as the
// local bounds of Galin et al. 2020, "Segment Tracing", measured along the ray instead of
// declared). omega grows at most STEP_GROWTH_PER_STEP a step, up to a limit (nextOmega):
//  - Verified (u_maxStepGrowth <= 2, the default): the largest omega for which the unbounding
//    spheres of consecutive points still overlap on a field that falls at `steepest`, 2 / (1 +
//    steepest), with a margin. A step passes only when they do overlap (Keinert et al. 2014's test):
//    the two spheres, which the measured factor makes empty, then cover it, so no step crosses a
//    surface the plain march would meet. Auto-relaxation (Balint and Valasek 2018) after a
//    fallback, where Keinert's marcher stays at omega = 1 for the rest of the ray.
//  - Trusted (u_maxStepGrowth > 2): also omega = STEP_TARGET_FALL / steepest, so that a surface met
//    head-on where the field is as steep as the steepest so far is neared by that share of the gap
//    a step. Spheres cannot vouch for such a step; it is taken back when the estimate fell by more
//    than STEP_BACK_FALL of it, and a step that lands inside is bisected back to the crossing
//    (recoverOvershoot). It can still step across a thin part whose estimate is steeper than any
//    the ray met before (bench/stills/README.md measures what that costs, scene by scene).
// A step taken back returns to the floor: the previous point's estimate, which the measured factor
// makes safe, and omega grows again from 1. lastD stays the floor's estimate: the viewport's cone
// coverage and coarse hits read it as an empty sphere.
const float STEP_TARGET_FALL = 0.5;
const float STEP_BACK_FALL = 0.75;
const float STEP_GROWTH_PER_STEP = 2.0;
const float VERIFIED_MARGIN = 0.95;

// How much the estimate fell per unit of ray over a step of omega * lastD from lastD to d.
float estimateFall(float omega, float lastD, float d) { return (lastD - d) / (omega * lastD); }

// steepest, rounded up to five significant bits within [2^-13, 2^13]: exact in half precision, as
// the viewport keeps it between frames (packStepState), so a ray resumed from the image steps as one
// marched through; frexp and ldexp are exact, so the CPU mirror rounds alike.
const float STEEPEST_FLOOR = 1.0 / 8192.0;
float quantizedSteepest(float x) {
    int e;
    float m = frexp(clamp(x, STEEPEST_FLOOR, 8192.0), e);
    return ldexp(ceil(m * 16.0) / 16.0, e);
}

// omega as a multiple of 1/32, which half precision holds exactly up to 64 (kMaxStepGrowth): the
// viewport keeps it in half a channel between frames (packStepState), and the step taken must be
// omega * lastD as stored (quantizedOmega in core/cpu_render/sphere_trace.hpp).
float quantizedOmega(float omega) { return floor(omega * 32.0) / 32.0; }

// omega for the step from a point whose estimate is d and hit threshold `threshold`, after a step of
// omega, where the steepest fall the ray has met is `steepest`. The verified limit is the omega
// whose step would pass stepTakenBack on a field falling at `steepest`.
float nextOmega(float omega, float steepest, float d, float threshold) {
    float limit = min(VERIFIED_MARGIN * (2.0 - threshold / d) / (1.0 + steepest), u_maxStepGrowth);
    if (u_maxStepGrowth > 2.0) limit = max(limit, min(STEP_TARGET_FALL / steepest, u_maxStepGrowth));
    return quantizedOmega(clamp(min(omega * STEP_GROWTH_PER_STEP, limit), 1.0, max(u_maxStepGrowth, 1.0)));
}

// Whether a step of omega * lastD along which the estimate went from lastD to d is taken back;
// `threshold` is the hit threshold where it ended. A verified step must have its ends' spheres
// overlap by a threshold: along it the estimate, 1-Lipschitz, then stays at or above half the
// overlap, half a threshold, which is all a plain step guarantees too (from lastD to d > threshold
// the estimate stays above d / 2). So a longer step skips no grazing ray's close approach to an
// edge that the plain march could not skip as well.
bool stepTakenBack(float omega, float lastD, float d, float threshold) {
    if (omega <= 1.0) return false;
    return omega < 2.0 ? d + lastD < omega * lastD + threshold : d < lastD * (1.0 - STEP_BACK_FALL);
}

const int MARCH_MARCHING = 0, MARCH_HIT = 1, MARCH_ESCAPED = 2;
struct MarchState {
    float t;      // distance along the ray
    float lastD;  // |DE| at the previous accepted point (0 before the first step); after a hit, the DE there
    float omega;  // the step's multiple of the estimate (the adaptive step, above); 1 after a step taken back
    int status;
    int steps;    // DE evaluations made by this ray's marcher
    float closest;  // the smallest d / t of the points passed (not the hit): half-angle of an empty cone
    float steepest;  // the steepest fall of the estimate per unit of ray the ray has met (the adaptive step)
};

// Hit refinement. The march stops at the first point with d < threshold, anywhere in the hit band
// [0, threshold): where depends on where the ray started, so a ray resumed from a reprojected start
// and one restarted at the camera stop at different depths, and on a fractal's sub-pixel texture a
// different depth is a different colour (bench/README.md, "what limits equal error"). A few signed
// steps toward the level set d = REFINE_LEVEL * threshold (t += d - level: never past that level
// set while the DE is 1-Lipschitz, and back toward it from inside) make the hit point nearly
// independent of the start. REFINE_STEPS moves cost REFINE_STEPS - 1 extra DE evaluations.
const int REFINE_STEPS = 3;
const float REFINE_LEVEL = 0.5;

void refineHit(vec3 ro, vec3 rd, float pixelAngle, float d, inout MarchState s, inout float deEvals) {
#if defined(FRAKTAL_HIT_INSIDE_ONLY) || defined(FRAKTAL_HIT_INTERIOR_WALLS)
    return;  // the hit is the rule's own (a bisected crossing, a band); the estimate's level sets are not the surface
#endif
    for (int i = 0; i < REFINE_STEPS; ++i) {
        if (i > 0) {
            d = DE(ro + rd * s.t);
            deEvals += 1.0;
            s.steps += 1;
        }
        s.t += d - REFINE_LEVEL * pixelAngle * s.t * u_detail;
    }
}

MarchState marchStart(float tStart) {
    return MarchState(tStart, 0.0, quantizedOmega(max(u_overRelaxation, 1.0)), MARCH_MARCHING, 0, 1e30, STEEPEST_FLOOR);
}

// Overshoot recovery. A step factor measured on sampled rays can still carry a ray across the
// surface where no sampled ray looked (a thin shell, a jump): the point it lands on is inside the
// object by the estimator's membership (formulaInside: the orbit stayed bounded, or the estimate
// is negative; a 1-Lipschitz estimate can drop by no more than the step, so a negative one after
// a plain step is the same test). The step is then bisected on membership between the point it
// left, which was outside, and the one it reached, as the seed's baseline marcher refines its
// crossing (3.1), until the crossing is known to within the hit threshold; the outside end is the
// hit. A ray whose steps stay outside pays nothing: membership comes with each estimate.
const int RECOVER_BISECTIONS = 12;

// [tOut, tIn] with tOut outside (its DE dOut) and tIn inside, bisected to within the hit
// threshold at tOut (at most RECOVER_BISECTIONS halvings): the hit at the outside end, with the
// smaller of its DE and the gap to the inside end as the distance the refinement starts from.
void recoverOvershoot(vec3 ro, vec3 rd, float tOut, float dOut, float tIn, float pixelAngle, inout MarchState s,
                      inout float deEvals) {
    for (int i = 0; i < RECOVER_BISECTIONS && tIn - tOut > pixelAngle * tOut * u_detail; ++i) {
        float tMid = 0.5 * (tOut + tIn);
        bool inside;
        float d = DEInside(ro + rd * tMid, inside);
        deEvals += 1.0;
        s.steps += 1;
        if (inside) {
            tIn = tMid;
        } else {
            tOut = tMid;
            dOut = d;
        }
    }
    s.t = tOut;
    s.lastD = min(dOut, tIn - tOut);
    s.status = MARCH_HIT;
}

// The marcher without the hit refinement; a hit leaves the DE at the hit point in lastD, so that
// the refinement can follow later (the viewport skips it for a pixel that keeps a carried colour:
// that hit point is not shaded).
#ifdef FRAKTAL_HIT_INTERIOR_WALLS
// Formula::hitRule InteriorWalls (why: core/formula.hpp), as Mandelbulber2 marches it (RayMarching
// in render_worker.cpp): the estimate, where the set's inside counts as the threshold
// (interiorWalls in formula.glsl), stops the ray below the threshold, and a step is the estimate
// less 0.8 thresholds. From outside that lands in the hit band [0.5, 1) x threshold where the
// estimate is exact; inside the set it is a fifth of the threshold, on to the wall where the ray
// comes out. Neither over-relaxed nor recovered: a step that lands inside crawls on, as in
// Mandelbulber2. A camera inside the set (threshold 0 at t = 0) sees it at once, as Mandelbulber2's
// stalled ray does.
void marchSteps(vec3 ro, vec3 rd, float tEnd, float pixelAngle, int maxSteps, inout MarchState s, inout float deEvals) {
    for (int i = 0; i < maxSteps && s.status == MARCH_MARCHING; ++i) {
        // Past tEnd (the bound sphere, a camera ray's view distance, a shadow ray's light) nothing
        // counts, not even a hit.
        if (s.t > tEnd) {
            s.status = MARCH_ESCAPED;
            break;
        }
        float threshold = pixelAngle * s.t * u_detail;
        hitThreshold = threshold;
        float d = DE(ro + rd * s.t);
        hitThreshold = 0.0;
        deEvals += 1.0;
        s.steps += 1;
        if (d < threshold || d <= 0.0) {
            s.lastD = max(d, 0.0);
            s.status = MARCH_HIT;
            break;
        }
        s.lastD = d;
        s.closest = min(s.closest, d / max(s.t, 1e-20));
        s.t += d - 0.8 * threshold;
    }
}
#else
void marchSteps(vec3 ro, vec3 rd, float tEnd, float pixelAngle, int maxSteps, inout MarchState s, inout float deEvals) {
    for (int i = 0; i < maxSteps && s.status == MARCH_MARCHING; ++i) {
        // Past tEnd (the bound sphere, a camera ray's view distance, a shadow ray's light) nothing
        // counts, not even a hit.
        if (s.t > tEnd) {
            s.status = MARCH_ESCAPED;
            break;
        }
        bool inside;
        hitThreshold = pixelAngle * s.t * u_detail;
        float d = DEInside(ro + rd * s.t, inside);
        hitThreshold = 0.0;
        deEvals += 1.0;
        s.steps += 1;
#ifdef FRAKTAL_HIT_INSIDE_ONLY
        // HitRule::InsideOnly: outside, the estimate never stops the ray (a step of at least the
        // threshold, Mandelbulber2's 1.01 detail sizes); inside, 0, so a step that reaches it is
        // bisected back by the overshoot recovery below and a ray that starts there hits at once.
        d = inside ? 0.0 : max(d, 1.01 * pixelAngle * s.t * u_detail);
#endif
        // Every step is omega * lastD (omega as it was when the step was taken), so the previous
        // step's length is known.
        float previousStep = s.omega * s.lastD;
        if (s.lastD > 0.0) s.steepest = quantizedSteepest(max(s.steepest, estimateFall(s.omega, s.lastD, abs(d))));
        if (s.lastD > 0.0 && stepTakenBack(s.omega, s.lastD, abs(d), pixelAngle * s.t * u_detail)) {
            // Back to the edge of the previous point's sphere (the floor's safe step), from which
            // omega grows again.
            s.t -= previousStep - s.lastD;
            s.omega = 1.0;
            continue;
        }
        if (inside && s.lastD > 0.0) {  // the step from the previous point crossed the surface
            recoverOvershoot(ro, rd, s.t - previousStep, s.lastD, s.t, pixelAngle, s, deEvals);
            if (s.t > tEnd) s.status = MARCH_ESCAPED;  // the crossing lies past the end
            break;
        }
        // At or below the threshold: an estimate of 0 at the ray's start (a camera inside an
        // escape-time object, where the threshold is 0 too) is a hit, not a step of nothing.
        if (d <= pixelAngle * s.t * u_detail) {
            s.lastD = d;
            s.status = MARCH_HIT;
            break;
        }
        if (s.lastD > 0.0) s.omega = nextOmega(s.omega, s.steepest, abs(d), pixelAngle * s.t * u_detail);
        s.lastD = abs(d);
        s.closest = min(s.closest, s.lastD / max(s.t, 1e-20));
        s.t += s.omega * d;
    }
}
#endif

// Whether a marched ray counts as a hit: it stopped on a surface, or it ran out of steps crawling
// along a grazing one (its last estimate within 10 thresholds). With interior walls a ray out of
// steps is still crossing the set: background, as in Mandelbulber2.
bool countsAsHit(MarchState s, float pixelAngle) {
#ifdef FRAKTAL_HIT_INTERIOR_WALLS
    return s.status == MARCH_HIT;
#else
    return s.status == MARCH_HIT || (s.status == MARCH_MARCHING && s.lastD < 10.0 * pixelAngle * s.t * u_detail);
#endif
}

void marchRay(vec3 ro, vec3 rd, float tEnd, float pixelAngle, int maxSteps, inout MarchState s, inout float deEvals) {
    marchSteps(ro, rd, tEnd, pixelAngle, maxSteps, s, deEvals);
    if (s.status == MARCH_HIT) refineHit(ro, rd, pixelAngle, s.lastD, s, deEvals);
}

// The part of the ray inside the bound sphere (radius u_boundRadius about the origin), where the
// DE is trusted. False when the ray misses the sphere or it lies behind the origin of the ray.
bool clipToBound(vec3 ro, vec3 rd, out float tStart, out float tEnd) {
    float b = dot(ro, rd);
    float c = dot(ro, ro) - u_boundRadius * u_boundRadius;
    float h = b * b - c;
    tStart = 0.0;
    tEnd = -1.0;
    if (h < 0.0) return false;
    h = sqrt(h);
    tStart = max(-b - h, 0.0);
    tEnd = -b + h;
    return tEnd > 0.0;
}

// A camera ray's part within the bound sphere and within u_viewDistance of the camera (0: no
// limit; RenderSettings::viewDistance, Mandelbulber2's view_distance_max).
bool clipCameraRay(vec3 ro, vec3 rd, out float tStart, out float tEnd) {
    if (!clipToBound(ro, rd, tStart, tEnd)) return false;
    if (u_viewDistance > 0.0) tEnd = min(tEnd, u_viewDistance);
    return tEnd > tStart;
}
