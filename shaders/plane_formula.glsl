// 2D formula template. The generator (core/plane/plane_glsl.cpp) replaces each //@ marker with
// code built from the formula's node lists; values are uniforms, so only a change of structure
// recompiles. Mirrors fraktal::evaluatePlane() on the CPU. `real` is double where the driver has
// fp64 (FRAKTAL_PLANE_FP64, deep zooms) and float otherwise.
#ifdef FRAKTAL_PLANE_FP64
#define real double
#define real2 dvec2
#else
#define real float
#define real2 vec2
#endif
#define FRAKTAL_MAX_ITERATIONS 1000

uniform int u_iterations;
uniform float u_bailout;

struct PlaneState {
    real2 z;         // the point
    real dz;         // running scale, or the derivative bound |dz/dc|
    float power;     // degree of the last power step (smooth iteration count)
    bool escaped;    // decided outside
    bool captured;   // decided inside
};

// Signed distance to the equilateral triangle pointing up, centroid at the origin, circumradius
// `radius` (Inigo Quilez, sdEquilateralTriangle). Twin of fraktal::planeSdTriangle.
real planeSdTriangle(real2 p, real radius) {
    real k = sqrt(real(3.0));
    real r = radius * k * 0.5;
    p.x = abs(p.x) - r;
    p.y = p.y + r / k;
    if (p.x + k * p.y > 0.0) p = real2(p.x - k * p.y, -k * p.x - p.y) / 2.0;
    p.x -= clamp(p.x, -2.0 * r, real(0.0));
    return -length(p) * sign(p.y);
}

//@PLANE_NODES

// The estimator's distance at pos; iterations: how many ran before the orbit was decided;
// smoothIterations: the continuous count (fraktal::planeSmoothIterations); inside: membership.
float planeEval(real2 pos, out int iterations, out float smoothIterations, out bool inside) {
    PlaneState s = PlaneState(pos, real(1.0), 1.0, false, false);
    real2 c = pos;
//@PLANE_START
    real bailout2 = real(u_bailout) * real(u_bailout);
    int n = clamp(u_iterations, 0, FRAKTAL_MAX_ITERATIONS);
    iterations = 0;
    bool passedBailout = false;
    if (!s.escaped && !s.captured) {
        for (int i = 0; i < n; ++i) {
//@PLANE_LOOP
            iterations = i + 1;
            if (s.escaped || s.captured) break;
            if (dot(s.z, s.z) > bailout2) {
                s.escaped = true;
                passedBailout = true;
                break;
            }
        }
    }
    smoothIterations = float(iterations);
    float r = float(length(s.z));
    if (passedBailout && s.power > 1.0 && r > 1.0 && u_bailout > 1.0)
        smoothIterations -= log(log(r) / log(u_bailout)) / log(s.power);
//@PLANE_ESTIMATE
//@PLANE_INSIDE
    return d;
}
