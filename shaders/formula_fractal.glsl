// One fractal of a formula, instantiated by the generator (core/glsl_gen.cpp) once per fractal,
// with `@F` replaced by its suffix: "" for the first, "_f1", "_f2"... for those combined with it
// (Formula::fractals). Its uniforms, its orbit, its membership and its estimate; mirrors
// evaluateFractal() and evaluatePlaced() in core/formula.cpp.
//@FRAKTAL_FRACTAL_OPTIONS

uniform int u_iterations@F;
uniform float u_bailout@F;
uniform float u_deFactor@F;
// Its placement (FractalPlacement): the point moved, repeated, turned and scaled into the
// fractal's frame; the estimate divided by the scale.
uniform vec3 u_fractalCenter@F;
uniform mat3 u_fractalTurn@F;
uniform float u_fractalScale@F;
uniform vec3 u_fractalRepeat@F;

#ifdef FRAKTAL_ORBIT_GRADIENT@F
// The orbit gradient, for estimators that read it (P4::orbitGradient); mirrors orbitValue and
// orbitValueGradient in core/formula.cpp.
// The estimator's orbit value at pos's orbit after exactly `count` iterations: log r for
// escape-time estimators, the estimate at w = 1 for distance ones.
float orbitValue@F(vec3 pos, int count) {
    vec4 p = vec4(pos, 1.0);
    vec3 c = pos;
    float degree = 1.0;
    orbitDistance = 1000.0;
    varyScale = 0.0;
    pointW = 0.0;
    for (int i = 0; i < count; ++i) {
        iteration = i;
//@FRAKTAL_ORBIT_LOOP
    }
//@FRAKTAL_ORBIT_VALUE
}

// |grad V| at pos by tetrahedral differences: for the vertices k of a regular tetrahedron,
// sum k (k . g) = 4 g.
float orbitValueGradient@F(vec3 pos, int count, float h) {
    const vec2 k = vec2(1.0, -1.0);
    vec3 g = k.xyy * orbitValue@F(pos + h * k.xyy, count) + k.yyx * orbitValue@F(pos + h * k.yyx, count) +
             k.yxy * orbitValue@F(pos + h * k.yxy, count) + k.xxx * orbitValue@F(pos + h * k.xxx, count);
    return length(g) / (4.0 * h);
}
#endif

// Membership by the estimator's rule (isInside in core/formula.hpp): escape-time estimators are
// inside where the orbit stayed bounded, distance ones where the estimate is <= 0.
bool fractalInside@F(float d, bool escaped) {
//@FRAKTAL_MEMBERSHIP
}

// The estimate at the world point `world`, as formulaEval returns it for this fractal alone.
float fractalEval@F(vec3 world, out vec4 trap, out int iterations, out bool escaped) {
    vec3 pos = u_fractalScale@F * (u_fractalTurn@F * repeatCell(world - u_fractalCenter@F, u_fractalRepeat@F));
    vec4 p = vec4(pos, 1.0);
    vec3 c = pos;
    float degree = 1.0;  // the power steps' degrees multiplied (P4::degree on the CPU)
    trap = vec4(1e20);
    orbitDistance = 1000.0;
    varyScale = 0.0;
    pointW = 0.0;
    iterations = 0;
    escaped = false;
    float bailout2 = u_bailout@F * u_bailout@F;
    int n = clamp(u_iterations@F, 0, FRAKTAL_MAX_ITERATIONS);
#ifdef FRAKTAL_WHOLE_DE@F
    n = 0;  // a whole DE (core/whole_de.hpp) runs its own iterations in the estimator
#endif
    for (int i = 0; i < n; ++i) {
        iteration = i;
//@FRAKTAL_LOOP
        trap = min(trap, vec4(abs(p.xyz), length(p.xyz)));
        iterations = i + 1;
        if (dot(p.xyz, p.xyz) + pointW * pointW > bailout2) {
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
    float surfaceLogR = allLog2 > 0.0 ? log(u_bailout@F) * exp2(-remainingLog2) : 0.0;
    float orbitGradient = 0.0;
#ifdef FRAKTAL_ORBIT_GRADIENT@F
    // The difference step: 0.02 of the estimate with the running derivative (the estimator
    // without the gradient), so that the orbit value is close to linear across it (the
    // tetrahedral stencil's error is first order in the step: 0.9% on the squaring ball at 0.02,
    // tests/de_quality_test.cpp), and no finer than single precision resolves at pos. 0 there
    // (inside, for escape-time estimates): no gradient.
//@FRAKTAL_RUNNING_ESTIMATE
    float reach = 1.0 + length(pos);
    if (running > 0.0)
        orbitGradient = orbitValueGradient@F(pos, iterations, clamp(0.02 * running, 1e-5 * reach, 1e-2 * reach));
#endif
//@FRAKTAL_ESTIMATE
}
