// shaders/viewport_neighbour_min.comp — starts every pixel's ray for a new view. After a
// reprojection (u_resetAll = 0) it is the seed's second erosion fix (4.2): the start is the
// minimum reprojected distance over the 3x3 neighbourhood (which also fills the scatter's
// one-pixel gaps), backed off by a margin and verified
// with the DE (a start within the hit threshold of a surface may lie behind a thin shell: such a
// ray restarts). Pixels nothing was reprojected onto (disoccluded, off-screen) restart from the
// camera, or from the cone pre-pass distance. The verifying DE is also the ray's first march step.
// Carried colours (with the surface point each is the shading of) go to sampleColor and
// colourPoint. A reset (u_resetAll = 1) restarts every pixel and keeps the old image until the new
// samples replace it. Needs the formula, march.glsl and viewport_common.glsl.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f, binding = 0) uniform image2D u_rayState;
layout(rgba32i, binding = 1) uniform iimage2D u_rayInfo;
layout(rgba32f, binding = 2) uniform image2D u_sampleColor;
layout(rgba32f, binding = 4) uniform image2D u_image;
layout(rgba32f, binding = 5) uniform image2D u_centre;
layout(r32f, binding = 6) uniform readonly image2D u_cone;
// The reprojection's nearest distance keys (viewport_reproject.comp); the first u_size.x *
// u_size.y are the start points': a distance's float bits, all ones where nothing landed.
layout(std430, binding = 1) readonly buffer ReprojectDepth { uint u_depth[]; };
// u_size.x by 2 u_size.y: the colour whose point lies in the pixel, then the one near it
layout(binding = 1) uniform sampler2D u_reprojColor;    // rgb, a: carry age + 1 (0: no colour)
layout(binding = 2) uniform sampler2D u_reprojCarried;  // xyz: the carried colour's point, w: its t
layout(rgba32f, binding = 10) uniform writeonly image2D u_colourPoint;
uniform int u_resetAll;
uniform int u_coneTile;  // 0: no cone pre-pass

// The distance of the reprojected point that won pixel q, or 1e30 when none landed there.
float reprojectedDistance(ivec2 q) {
    uint key = u_depth[q.y * u_size.x + q.x];
    return key == 0xFFFFFFFFu ? 1e30 : uintBitsToFloat(key);
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, u_size))) return;
    vec3 ro = u_cameraPosition;
    vec3 rd = cameraRay(vec2(px) + 0.5);
    float tStart, tEnd;
    bool inBound = clipToBound(ro, rd, tStart, tEnd);
    float restartAt = tStart;
    if (u_coneTile > 0) restartAt = max(tStart, imageLoad(u_cone, px / u_coneTile).x);

    float t = restartAt;
    bool reprojected = false;
    int flags = 0;
    vec4 carried = vec4(0.0, 0.0, 0.0, -1.0);
    float carryAge = 0.0;
    float deEvals = 0.0;
    // The colour whose point lies in this pixel, else the nearest of those that lie within half a
    // pixel diagonal of its centre (viewport_reproject.comp): each keeps its own point, so the
    // sample stays where it belongs on the surface.
    ivec2 colourFrom = px;
    vec4 carriedColor = u_resetAll != 0 ? vec4(0.0) : texelFetch(u_reprojColor, px, 0);
    if (u_resetAll == 0 && carriedColor.a == 0.0) {
        colourFrom = ivec2(px.x, u_size.y + px.y);
        carriedColor = texelFetch(u_reprojColor, colourFrom, 0);
    }
    vec4 colourPoint = vec4(0.0);
    if (carriedColor.a > 0.0) {
        vec4 point = texelFetch(u_reprojCarried, colourFrom, 0);
        carried = vec4(carriedColor.rgb, point.w);
        colourPoint = vec4(point.xyz, 1.0);
        carryAge = carriedColor.a;
        flags |= FLAG_CARRIED;
        imageStore(u_image, px, vec4(carried.rgb, 1.0));
    }
    // The minimum over the neighbourhood also fills the one-pixel gaps the reprojection scatter
    // leaves where the view magnifies (nothing landed here, but on both sides).
    float tMin = 1e30;
    if (u_resetAll == 0)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dx = -1; dx <= 1; ++dx)
                tMin = min(tMin, reprojectedDistance(clamp(px + ivec2(dx, dy), ivec2(0), u_size - 1)));
    float omega = max(u_overRelaxation, 1.0);
    float lastD = 0.0, covered = t;
    int steps = 0;
    if (tMin < 1e30) {
        float candidate = tMin - reprojectionMargin(tMin, u_pixelAngle, u_detail);
        if (inBound && candidate >= tEnd) {
            // Beyond the bound sphere's far side: nothing to verify, the ray escapes (no DE).
            t = candidate;
            reprojected = true;
        } else if (inBound && candidate > restartAt) {
            float d = DE(ro + rd * candidate);
            deEvals += 1.0;
            if (d >= u_pixelAngle * candidate * u_detail) {
                // The verifying DE is also the ray's first march step (as marchRay would take it).
                covered = candidate;
                t = candidate + omega * d;
                lastD = d;
                steps = 1;
                reprojected = true;
            }
        }
    }
    imageStore(u_rayState, px, vec4(t, lastD, omega, covered));
    imageStore(u_rayInfo, px, ivec4(STATUS_MARCHING, steps, 0, flags));
    imageStore(u_sampleColor, px, carried);
    imageStore(u_centre, px, vec4(t, float(STATUS_MARCHING), carryAge, 0.0));
    imageStore(u_colourPoint, px, colourPoint);
    atomicAdd(c_deEvals, uint(deEvals));
    if (reprojected) atomicAdd(c_reprojected, 1u);
    else atomicAdd(c_restarted, 1u);
}
