// shaders/lens.glsl — the thin lens (pbrt-v4's ThinLensCamera): a camera ray leaves a point on the
// aperture and passes through the point its pinhole ray reaches on the plane of focus, so
// surfaces at the focus distance stay sharp and the rest blurs by the circle of confusion.
// Shared by the path tracer (pathtrace.frag; its CPU mirror is core/cpu_render/cpu_path_tracer.cpp,
// sampleAperture) and the fast still renderer (still.frag). Uniforms: u_apertureRadius (world
// units; 0: pinhole), u_focusDistance (along the view axis), u_blades (0: round; 3..16 sides).
uniform float u_apertureRadius, u_focusDistance;
uniform int u_blades;

// The radical inverse of i in `base` (its digits mirrored about the point): the i-th point of
// the van der Corput sequence, one coordinate of the Halton sequence that places lens samples.
float radicalInverse(int i, int base) {
    float inverseBase = 1.0 / float(base), f = inverseBase, result = 0.0;
    for (int n = i; n > 0; n /= base) {
        result += f * float(n % base);
        f *= inverseBase;
    }
    return result;
}

// A point on the unit aperture from two uniform numbers: Shirley and Chiu's concentric map onto
// the disc, or for blades >= 3 a uniform point of the regular polygon (a triangle fan).
vec2 sampleAperture(float u1, float u2, int blades) {
    const float pi = 3.14159265358979323846;
    if (blades < 3) {
        float a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
        if (a == 0.0 && b == 0.0) return vec2(0.0);
        float r, phi;
        if (abs(a) > abs(b)) {
            r = a;
            phi = (pi / 4.0) * (b / a);
        } else {
            r = b;
            phi = pi / 2.0 - (pi / 4.0) * (a / b);
        }
        return vec2(r * cos(phi), r * sin(phi));
    }
    float scaled = u1 * float(blades);
    int k = min(int(scaled), blades - 1);
    float v1 = scaled - float(k);
    float a0 = pi / 2.0 + 2.0 * pi * float(k) / float(blades), a1 = a0 + 2.0 * pi / float(blades);
    float su = sqrt(v1);
    float wa = su * (1.0 - u2), wb = su * u2;
    return vec2(wa * cos(a0) + wb * cos(a1), wa * sin(a0) + wb * sin(a1));
}

// Moves the pinhole ray (ro, rd) of a camera with the given frame onto the lens at the aperture
// point made from (u1, u2). A pinhole (u_apertureRadius 0) leaves it as it is.
void thinLensRay(inout vec3 ro, inout vec3 rd, vec3 forward, vec3 right, vec3 up, float u1, float u2) {
    if (u_apertureRadius <= 0.0) return;
    vec3 focusPoint = ro + rd * (u_focusDistance / dot(rd, forward));
    vec2 lens = sampleAperture(u1, u2, u_blades) * u_apertureRadius;
    ro = ro + right * lens.x + up * lens.y;
    rd = normalize(focusPoint - ro);
}
