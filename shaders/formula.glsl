// Distance estimator template. The generator (core/glsl_gen.cpp) replaces each //@ marker with
// code built from the formula's node list; values are uniforms, so only a change of structure
// (blocks, order, enable, schedule) recompiles. Each fractal of the formula (the first, and those
// combined with it) is an instance of shaders/formula_fractal.glsl. Mirrors fraktal::evaluate()
// on the CPU.
#define FRAKTAL_MAX_ITERATIONS 1000
//@FRAKTAL_HIT_RULE

uniform float u_boundRadius;

// formulaEval's surface where the fractals' distance is the result's (kFractalSurface in
// core/scene_object.hpp); an object's is its index in the formula's objects.
const int FRAKTAL_FRACTAL_SURFACE = -1;

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
// The iteration the orbit is on (P4::iteration), set by the loops before each iteration's nodes.
int iteration;
// The point's fourth coordinate (P4::pointW): the 4D steps read and change it; each orbit starts
// it at 0.
float pointW;

// A dIFS shape step's divisor (difsDivisor in formulas/difs.hpp): |p.w| times the step's scale,
// the varying one with wVary, plus wOffset.
float difsDivisor(float w, float wScale, float wOffset, float wVary) {
    return abs(w) * abs(wScale + (wVary > 0.5 ? varyScale : 0.0)) + wOffset;
}

// The hit threshold at the point the marcher evaluates, 0 in any other evaluation (evaluate()'s
// hitThreshold in core/formula.cpp): interior walls and fractals carved by an escape-time one
// read it.
float hitThreshold = 0.0;

#ifdef FRAKTAL_HIT_INTERIOR_WALLS
// Formula::hitRule InteriorWalls: the fractal's estimate as the marcher sees it, before the
// objects: the set's inside, and its outside within half the threshold, count as the threshold
// (mirrors evaluate() in core/formula.cpp).
float interiorWalls(float d, bool inside, float threshold) {
    return threshold > 0.0 && (inside || d < 0.5 * threshold) ? threshold : d;
}
#endif

// The cell a repeated point falls in, centred on the origin; an axis of period 0 is kept
// (repeatCell in core/formula.cpp).
vec3 repeatCell(vec3 x, vec3 period) {
    return mix(x, x - period * floor(x / period + 0.5), greaterThan(period, vec3(0.0)));
}

// How many of the iterations 0 .. count - 1 a node of this schedule runs on
// (IterationSchedule::iterationsRunBefore).
int cycleRunsBefore(int count, int period, int phase) {
    return count > phase ? (count - phase - 1) / period + 1 : 0;
}
int iterationsRunBefore(int count, int period, int phase, int start, int stop) {
    return cycleRunsBefore(min(count, stop), period, phase) - cycleRunsBefore(min(count, start), period, phase);
}

//@FRAKTAL_NODES

// Returns the distance estimate at pos; trap receives the orbit trap (min |x|, |y|, |z| and
// min |p| over the iterations, seed 3.3); iterations the count before escape; escaped whether
// the orbit passed the bailout (membership for escape-time formulas). Of combined fractals, the
// trap and count of the fractal that set the distance, and escaped the combined membership's
// flag (not inside). surface: FRAKTAL_FRACTAL_SURFACE, or the index of the object beside the
// fractal whose distance the result is (combineObjects in core/scene_object.cpp).
float formulaEval(vec3 pos, out vec4 trap, out int iterations, out bool escaped, out int surface) {
//@FRAKTAL_COMBINE
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
    int surface;
    float d = formulaEval(pos, trap, iterations, escaped, surface);
    inside = formulaInside(d, escaped);
    return d;
}

float formulaDE(vec3 pos, out vec4 trap, out int iterations) {
    bool escaped;
    int surface;
    return formulaEval(pos, trap, iterations, escaped, surface);
}

// The surface at pos (as formulaEval's) and the orbit trap there: what the shading colours by.
float formulaSurface(vec3 pos, out vec4 trap, out int surface) {
    int iterations;
    bool escaped;
    return formulaEval(pos, trap, iterations, escaped, surface);
}

float DE(vec3 pos) {
    vec4 trap;
    int iterations;
    return formulaDE(pos, trap, iterations);
}
