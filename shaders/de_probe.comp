// Evaluates the formula's DE at a list of points: the GPU side of the GPU/CPU agreement tests,
// and how the CPU side reads a formula it cannot evaluate itself (custom GLSL blocks).
layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Points { vec4 points[]; };
// Two vec4 per point: (distance, iterations, escaped, surface) and the orbit trap.
layout(std430, binding = 1) writeonly buffer Results { vec4 results[]; };

uniform uint u_count;

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= u_count) return;
    vec4 trap;
    int iterations;
    bool escaped;
    int surface;
    float d = formulaEval(points[i].xyz, trap, iterations, escaped, surface);
    results[2u * i] = vec4(d, float(iterations), escaped ? 1.0 : 0.0, float(surface));
    results[2u * i + 1u] = trap;
}
