// shaders/march.glsl — needs DE() from the formula (shaders/formula.glsl, which also declares
// u_boundRadius).
//
// Sphere tracing with over-relaxation and fallback (Keinert et al. 2014, "Enhanced Sphere Tracing",
// section 3.1): step omega * d while consecutive unbounding spheres overlap; when they stop
// overlapping the over-relaxed step may have jumped over surface, so step back to the plain
// sphere-tracing step from the previous point and continue with omega = 1. Hit when
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
uniform float u_detail;
uniform float u_overRelaxation;

const int MARCH_MARCHING = 0, MARCH_HIT = 1, MARCH_ESCAPED = 2;
struct MarchState {
    float t;      // distance along the ray
    float lastD;  // |DE| at the previous accepted point (0 before the first step); after a hit, the DE there
    float omega;  // current relaxation factor; drops to 1 at the first failure
    int status;
    int steps;    // DE evaluations made by this ray's marcher
    float closest;  // the smallest d / t of the points passed (not the hit): half-angle of an empty cone
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
    return MarchState(tStart, 0.0, max(u_overRelaxation, 1.0), MARCH_MARCHING, 0, 1e30);
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
        if (s.t > tEnd) {
            s.status = MARCH_ESCAPED;
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
        // While omega > 1 every step so far was omega * lastD, so the previous step length is known.
        float previousStep = s.omega * s.lastD;
        if (s.omega > 1.0 && abs(d) + s.lastD < previousStep) {
            // The unbounding spheres of the last two points do not overlap: back to the edge of the
            // previous point's sphere (a safe plain step) and never over-relax again on this ray.
            s.t -= previousStep - s.lastD;
            s.omega = 1.0;
            continue;
        }
        if (inside && s.lastD > 0.0) {  // the step from the previous point crossed the surface
            recoverOvershoot(ro, rd, s.t - previousStep, s.lastD, s.t, pixelAngle, s, deEvals);
            break;
        }
        // At or below the threshold: an estimate of 0 at the ray's start (a camera inside an
        // escape-time object, where the threshold is 0 too) is a hit, not a step of nothing.
        if (d <= pixelAngle * s.t * u_detail) {
            s.lastD = d;
            s.status = MARCH_HIT;
            break;
        }
        if (s.t > tEnd) {
            s.status = MARCH_ESCAPED;
            break;
        }
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
