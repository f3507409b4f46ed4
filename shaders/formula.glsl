// Distance estimator template. The generator (core/glsl_gen.cpp) replaces each //@ marker with
// code built from the formula's node list; values are uniforms, so only a change of structure
// (blocks, order, enable, period, phase) recompiles. Mirrors fraktal::evaluate() on the CPU.
#define FRAKTAL_MAX_ITERATIONS 1000

uniform int u_iterations;
uniform float u_bailout;
uniform float u_deFactor;
uniform float u_boundRadius;

//@FRAKTAL_NODES

// How many of the iterations 0 .. count - 1 a node of this period and phase runs on
// (Node::iterationsRunBefore).
int iterationsRunBefore(int count, int period, int phase) {
    return count > phase ? (count - phase - 1) / period + 1 : 0;
}

// Returns the distance estimate at pos; trap receives the orbit trap (min |x|, |y|, |z| and
// min |p| over the iterations, seed 3.3); iterations the count before escape; escaped whether
// the orbit passed the bailout (membership for escape-time formulas).
float formulaEval(vec3 pos, out vec4 trap, out int iterations, out bool escaped) {
    vec4 p = vec4(pos, 1.0);
    vec3 c = pos;
    float degree = 1.0;  // the power steps' degrees multiplied (P4::degree on the CPU)
    trap = vec4(1e20);
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
//@FRAKTAL_ESTIMATE
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
