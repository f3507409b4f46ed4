// shaders/viewport_start.glsl — where every pixel's ray starts for a new view, for the march
// pass's START variant (viewport_march.comp), which marches on from there in the same invocation.
// After a reprojection (u_resetAll = 0) it is the seed's second erosion fix (4.2): the start is
// the minimum reprojected distance over the 3x3 neighbourhood (which also fills the scatter's
// one-pixel gaps), backed off by a margin, and the ray's first DE verifies it (a start within the
// hit threshold of a surface may lie behind a thin shell: such a ray restarts). Pixels nothing
// was reprojected onto (disoccluded, off-screen) restart from the camera, or from the cone
// pre-pass distance. Carried colours (with the surface point each is the shading of) go to
// sampleColor and colourPoint. A reset (u_resetAll = 1) restarts every pixel and keeps the old
// image until the new samples replace it.
//
// Until 2026-11 this was a pass of its own: it stored the whole march state for the march pass
// to load, and held a DE of its own for the verification. On llvmpipe every image store costs
// about 1.5 ms of a 640x360 frame and every DE in the code about 5 (the Mandelbulb's), whether
// or not a pixel needs it. Needs the formula, march.glsl and viewport_common.glsl.
layout(rgba32f) uniform writeonly image2D u_image;
layout(r32f) uniform readonly image2D u_cone;
// The reprojection's nearest distance keys (viewport_reproject.comp); the first u_size.y rows are
// the start points': a distance's float bits, all ones where nothing landed.
layout(r32ui) uniform uimage2D u_depth;
// u_size.x by 2 u_size.y: the colour whose point lies in the pixel, then the one near it
layout(binding = 1) uniform sampler2D u_reprojColor;    // rgb, a: carry age + 1 (0: no colour)
layout(binding = 2) uniform sampler2D u_reprojCarried;  // xyz: the carried colour's point, w: its t
uniform int u_resetAll;
uniform int u_coneTile;  // 0: no cone pre-pass

struct RayStart {
    float t;          // where the ray starts: from the camera, or a reprojected start
    float restartAt;  // where it restarts from the camera (or the cone pre-pass distance)
    bool verify;      // t is a reprojected start the ray's first DE verifies
    bool reprojected; // t is a reprojected start past the bound sphere: nothing to verify
    int flags;        // FLAG_CARRIED when a colour was carried here
    vec4 carried;     // rgb: the carried colour; a: its point's distance (-1: none)
    vec4 colourPoint; // xyz: the carried colour's point; w: 1 if there is one
    float carryAge;   // frames the carried colour has been carried (+1 here)
};

// The distance of the reprojected point that won pixel q, or 1e30 when none landed there.
float reprojectedDistance(ivec2 q) {
    uint key = imageLoad(u_depth, q).x;
    return key == 0xFFFFFFFFu ? 1e30 : uintBitsToFloat(key);
}

// The start of pixel px's centre ray (ro, rd) for the new view.
RayStart startRay(ivec2 px, vec3 ro, vec3 rd) {
    RayStart start;
    float tStart, tEnd;
    bool inBound = clipCameraRay(ro, rd, tStart, tEnd);
    start.restartAt = tStart;
    if (u_coneTile > 0) start.restartAt = max(tStart, imageLoad(u_cone, px / u_coneTile).x);
    start.t = start.restartAt;
    start.verify = false;
    start.reprojected = false;
    start.flags = 0;
    start.carried = vec4(0.0, 0.0, 0.0, -1.0);
    start.colourPoint = vec4(0.0);
    start.carryAge = 0.0;
    if (u_resetAll != 0) return start;
    // The colour whose point lies in this pixel, else the nearest of those that lie within half a
    // pixel diagonal of its centre (viewport_reproject.comp): each keeps its own point, so the
    // sample stays where it belongs on the surface.
    ivec2 colourFrom = px;
    vec4 carriedColor = texelFetch(u_reprojColor, px, 0);
    if (carriedColor.a == 0.0) {
        colourFrom = ivec2(px.x, u_size.y + px.y);
        carriedColor = texelFetch(u_reprojColor, colourFrom, 0);
    }
    if (carriedColor.a > 0.0) {
        vec4 point = texelFetch(u_reprojCarried, colourFrom, 0);
        start.carried = vec4(carriedColor.rgb, point.w);
        start.colourPoint = vec4(point.xyz, 1.0);
        start.carryAge = carriedColor.a;
        start.flags |= FLAG_CARRIED;
        imageStore(u_image, px, vec4(carriedColor.rgb, 1.0));
    }
    // The minimum over the neighbourhood also fills the one-pixel gaps the reprojection scatter
    // leaves where the view magnifies (nothing landed here, but on both sides).
    float tMin = 1e30;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx)
            tMin = min(tMin, reprojectedDistance(clamp(px + ivec2(dx, dy), ivec2(0), u_size - 1)));
    if (tMin < 1e30 && inBound) {
        float candidate = tMin - reprojectionMargin(tMin, u_pixelAngle, u_detail);
        if (candidate >= tEnd) {
            // Beyond the bound sphere's far side: nothing to verify, the ray escapes (no DE).
            start.t = candidate;
            start.reprojected = true;
        } else if (candidate > start.restartAt) {
            start.t = candidate;
            start.verify = true;
        }
    }
    return start;
}
