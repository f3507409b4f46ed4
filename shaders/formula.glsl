// Distance estimator template. The generator (core/glsl_gen.cpp) replaces each //@ marker with
// code built from the formula's node list; values are uniforms, so only a change of structure
// (blocks, order, enable, schedule) recompiles. Mirrors fraktal::evaluate() on the CPU.
#define FRAKTAL_MAX_ITERATIONS 1000
//@FRAKTAL_OPTIONS
//@FRAKTAL_HIT_RULE

uniform int u_iterations;
uniform float u_bailout;
uniform float u_deFactor;
uniform float u_boundRadius;

// (1 - e^-G) / G: the potential estimate's share of the log one (potentialShare in
// formulas/estimators.hpp, which says why the series).
float potentialShare(float G) {
    return G < 0.1 ? 1.0 - G * (1.0 / 2.0 - G * (1.0 / 6.0 - G * (1.0 / 24.0 - G / 120.0))) : (1.0 - exp(-G)) / G;
}

// The dIFS shapes' running least distance (P4::orbitDistance): the shape steps lower it, the dIFS
// estimator returns it; each orbit starts it afresh.
float orbitDistance;
// The varying scale's running offset (P4::varyScale): the scale_vary steps read and change it;
// each orbit starts it at 0.
float varyScale;

// A dIFS shape step's divisor (difsDivisor in formulas/difs.hpp): |p.w| times the step's scale,
// the varying one with wVary, plus wOffset.
float difsDivisor(float w, float wScale, float wOffset, float wVary) {
    return abs(w) * abs(wScale + (wVary > 0.5 ? varyScale : 0.0)) + wOffset;
}

#ifdef FRAKTAL_HIT_INTERIOR_WALLS
// Formula::hitRule InteriorWalls: the hit threshold at the point the marcher evaluates (0 in any
// other evaluation), and the fractal's estimate as the marcher sees it, before the objects: the
// set's inside, and its outside within half the threshold, count as the threshold (mirrors
// evaluate() in core/formula.cpp).
float interiorWallsThreshold = 0.0;
bool formulaInside(float d, bool escaped);
float interiorWalls(float d, bool escaped) {
    float threshold = interiorWallsThreshold;
    return threshold > 0.0 && (formulaInside(d, escaped) || d < 0.5 * threshold) ? threshold : d;
}
#endif

//@FRAKTAL_NODES

// How many of the iterations 0 .. count - 1 a node of this schedule runs on
// (IterationSchedule::iterationsRunBefore).
int cycleRunsBefore(int count, int period, int phase) {
    return count > phase ? (count - phase - 1) / period + 1 : 0;
}
int iterationsRunBefore(int count, int period, int phase, int start, int stop) {
    return cycleRunsBefore(min(count, stop), period, phase) - cycleRunsBefore(min(count, start), period, phase);
}

#ifdef FRAKTAL_ORBIT_GRADIENT
// The orbit gradient, for estimators that read it (P4::orbitGradient); mirrors orbitValue and
// orbitValueGradient in core/formula.cpp.
// The estimator's orbit value at pos's orbit after exactly `count` iterations: log r for
// escape-time estimators, the estimate at w = 1 for distance ones.
float orbitValue(vec3 pos, int count) {
    vec4 p = vec4(pos, 1.0);
    vec3 c = pos;
    float degree = 1.0;
    orbitDistance = 1000.0;
    varyScale = 0.0;
    for (int i = 0; i < count; ++i) {
//@FRAKTAL_ORBIT_LOOP
    }
//@FRAKTAL_ORBIT_VALUE
}

// |grad V| at pos by tetrahedral differences: for the vertices k of a regular tetrahedron,
// sum k (k . g) = 4 g.
float orbitValueGradient(vec3 pos, int count, float h) {
    const vec2 k = vec2(1.0, -1.0);
    vec3 g = k.xyy * orbitValue(pos + h * k.xyy, count) + k.yyx * orbitValue(pos + h * k.yyx, count) +
             k.yxy * orbitValue(pos + h * k.yxy, count) + k.xxx * orbitValue(pos + h * k.xxx, count);
    return length(g) / (4.0 * h);
}
#endif

// Returns the distance estimate at pos; trap receives the orbit trap (min |x|, |y|, |z| and
// min |p| over the iterations, seed 3.3); iterations the count before escape; escaped whether
// the orbit passed the bailout (membership for escape-time formulas).
float formulaEval(vec3 pos, out vec4 trap, out int iterations, out bool escaped) {
    vec4 p = vec4(pos, 1.0);
    vec3 c = pos;
    float degree = 1.0;  // the power steps' degrees multiplied (P4::degree on the CPU)
    trap = vec4(1e20);
    orbitDistance = 1000.0;
    varyScale = 0.0;
    iterations = 0;
    escaped = false;
    float bailout2 = u_bailout * u_bailout;
    int n = clamp(u_iterations, 0, FRAKTAL_MAX_ITERATIONS);
    for (int i = 0; i < n; ++i) {
//@FRAKTAL_LOOP
        trap = min(trap, vec4(abs(p.xyz), length(p.xyz)));
        iterations = i + 1;
        if (dot(p.xyz, p.xyz) > bailout2) {
            escaped = true;
            break;
        }
    }
    // log r on the surface the iteration count draws, in this orbit's units (P4::surfaceLogR):
    // the degrees of the iterations the orbit did not run divide log(bailout). Counted in log2
    // from each power node's count of runs: a loop over the remaining iterations cost 12 % of a
    // Mandelbulb still on llvmpipe.
    float remainingLog2 = 0.0, allLog2 = 0.0;
//@FRAKTAL_REMAINING_DEGREE
    float surfaceLogR = allLog2 > 0.0 ? log(u_bailout) * exp2(-remainingLog2) : 0.0;
    float orbitGradient = 0.0;
#ifdef FRAKTAL_ORBIT_GRADIENT
    // The difference step: 0.02 of the estimate with the running derivative (the estimator
    // without the gradient), so that the orbit value is close to linear across it (the
    // tetrahedral stencil's error is first order in the step: 0.9% on the squaring ball at 0.02,
    // tests/de_quality_test.cpp), and no finer than single precision resolves at pos. 0 there
    // (inside, for escape-time estimates): no gradient.
//@FRAKTAL_RUNNING_ESTIMATE
    float reach = 1.0 + length(pos);
    if (running > 0.0)
        orbitGradient = orbitValueGradient(pos, iterations, clamp(0.02 * running, 1e-5 * reach, 1e-2 * reach));
#endif
//@FRAKTAL_ESTIMATE
}

// Membership by the estimator's rule (isInside in core/formula.hpp): escape-time estimators are
// inside where the orbit stayed bounded, distance ones where the estimate is <= 0.
bool formulaInside(float d, bool escaped) {
//@FRAKTAL_MEMBERSHIP
}

// The estimate at pos and whether pos is inside the object (the marcher's overshoot test).
float DEInside(vec3 pos, out bool inside) {
    vec4 trap;
    int iterations;
    bool escaped;
    float d = formulaEval(pos, trap, iterations, escaped);
    inside = formulaInside(d, escaped);
    return d;
}

float formulaDE(vec3 pos, out vec4 trap, out int iterations) {
    bool escaped;
    return formulaEval(pos, trap, iterations, escaped);
}

float DE(vec3 pos) {
    vec4 trap;
    int iterations;
    return formulaDE(pos, trap, iterations);
}
