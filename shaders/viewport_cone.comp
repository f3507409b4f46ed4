// shaders/viewport_cone.comp — the optional low-resolution cone pre-pass: one cone per
// u_coneTile x u_coneTile block of pixels, wide enough to hold every pixel ray of the block, is
// sphere-traced while the DE proves its cross-section empty (extendConeCoverage). Full-resolution
// rays that restart begin where the cone first touched the surface instead of at the camera
// (the "cone marching" of Marble Marcher Community Edition). Needs the formula, march.glsl and
// viewport_common.glsl.
layout(local_size_x = 32, local_size_y = 8) in;  // viewport_common.glsl: why 32x8
layout(r32f) uniform writeonly image2D u_cone;
uniform int u_coneTile;
uniform int u_coneSteps;

void main() {
    ivec2 tile = ivec2(gl_GlobalInvocationID.xy);
    ivec2 tiles = (u_size + u_coneTile - 1) / u_coneTile;
    if (any(greaterThanEqual(tile, tiles))) return;
    vec3 ro = u_cameraPosition;
    vec3 rd = cameraRay((vec2(tile) + 0.5) * float(u_coneTile));
    // Pixel centres lie within (tile - 1) / sqrt(2) pixels of the tile centre; one extra pixel of slack.
    float tanHalf = (float(u_coneTile) * HALF_DIAGONAL + 1.0) * u_pixelAngle;
    float tStart, tEnd;
    float t = 0.0;
    float deEvals = 0.0;
    if (clipCameraRay(ro, rd, tStart, tEnd)) {
        t = tStart;
        for (int i = 0; i < u_coneSteps && t < tEnd; ++i) {
            float d = DE(ro + rd * t);
            deEvals += 1.0;
            float next = extendConeCoverage(t, t, d, tanHalf);
            if (next <= t) break;
            t = next;
        }
    }
    imageStore(u_cone, tile, vec4(t));
    atomicAdd(c_deEvals, uint(deEvals));
}
