// shaders/viewport_march.comp — progressive marching (seed 4.1): advances every unfinished ray
// by at most u_stepsPerFrame steps of march.glsl's marcher, resuming from the stored state. The
// START variant (#define START 1, on a reset or a reprojected frame) first starts every pixel's
// ray for the new view (viewport_start.glsl) and marches on from there; its first DE verifies a
// reprojected start. A ray that finished gets its colour here when that costs no DE (the
// background; a hit that keeps the colour reprojection carried to it); the others go on the list
// of pixels the shade pass shades (with, at rest, the reused colours to shade exactly). Shading
// them here would cost every pixel the shading code: llvmpipe (Mesa 22) runs both sides of every
// branch for a SIMD group, skipping nothing, so only a separate dispatch over a compacted list
// keeps shading off the other pixels. Needs the formula, march.glsl, shade.glsl,
// viewport_common.glsl and, for START, viewport_start.glsl before it.
//
// The same holds for the march loop itself: a SIMD group of 8 pixels steps until its last ray
// finishes, so one ray that needs the whole budget (restarted, or grazing past a silhouette)
// costs its 7 neighbours that many DE too, although after a reprojection most rays finish in a
// few steps. So on such a frame the full-screen pass marches at most u_deferAfter steps; a ray
// still marching then goes, with the rest of its budget, on the march list, and the FROM_LIST
// variant (one invocation per entry, 64-wide groups, dispatched indirectly) marches it on, with
// its SIMD neighbours also long rays. The rays take the same steps either way, bit for bit.
// (When most rays need many steps, on a reset or at rest, the list's loads and stores cost more
// than the idle lanes: core/viewport/march_pass.cpp does not defer there.)
#if FROM_LIST
layout(local_size_x = 64) in;  // SHADE_GROUP entries per group, as the list's header counts them
#else
layout(local_size_x = 32, local_size_y = 8) in;  // viewport_common.glsl: why 32x8
#endif
layout(rgba32f) uniform image2D u_rayState;
layout(rgba32i) uniform iimage2D u_rayInfo;
layout(rgba32f) uniform image2D u_sampleColor;
layout(rgba32f) uniform image2D u_centre;
layout(rgba32f) uniform writeonly image2D u_colourPoint;
uniform int u_stepsPerFrame;
uniform int u_maxCarryFrames;
uniform int u_maxSteps;
uniform int u_atRest;
uniform int u_coarseHits;  // ViewportOptions::coarseHits
uniform int u_deferAfter;  // the full-screen pass's steps before a ray goes on the march list
// Sliced refinement (core/viewport/march_pass.cpp): the frame advances only the tiles (the
// workgroups of the view, numbered row by row) whose number modulo u_sliceCount is u_sliceIndex,
// and the resuming variant is dispatched over those alone (one dimension, a workgroup a tile). A
// sliced reset starts no ray over the whole view: the resuming variant starts each ray of an older
// view (u_generation, viewport_common.glsl) when its slice first comes. A whole-view pass costs
// llvmpipe about 15 ms an image store at 690x520, whatever the pixel does: the start pass (five
// stores) took 60-160 ms, a frame at rest's whole budget three times over. A pixel's own sequence
// of steps, shading and samples is the same however the frames slice the view: only when it comes
// differs.
uniform int u_sliceCount;  // 1: every pixel
uniform int u_sliceIndex;

void main() {
#if FROM_LIST
    uint entry = gl_GlobalInvocationID.x;
    if (entry >= ml_count) return;
    ivec2 px = listedPixel(ml_entries[entry].x);
#elif START
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, u_size))) return;
#else
    ivec2 px = slicePixel(u_sliceCount, u_sliceIndex, ivec2(gl_WorkGroupSize.xy));
    if (any(greaterThanEqual(px, u_size))) return;
#endif
    vec3 ro = u_cameraPosition;
    float initialOmega = quantizedOmega(max(u_overRelaxation, 1.0));
#if START
    RayStart start = startRay(px, ro, cameraRay(vec2(px) + 0.5));
    ivec4 info = ivec4(STATUS_MARCHING, 0, 0, start.flags | (u_generation << GENERATION_SHIFT));
    vec4 state = vec4(start.t, 0.0, packStepState(initialOmega, STEEPEST_FLOOR), start.restartAt);
    bool verifying = start.verify;
    bool reprojected = start.reprojected;
    float tCarried = start.carried.a;
    float carryAge = start.carryAge;
#else
    ivec4 info = imageLoad(u_rayInfo, px);
#if FROM_LIST  // a listed ray is marching, in this view
    const bool fresh = false;
#else
    // A ray of an older view (a sliced reset starts none: this is its slice's first frame since)
    // starts from the camera here, as the START variant's reset would have started it.
    const bool fresh = (info.w >> GENERATION_SHIFT) != u_generation;
    if (fresh) info = ivec4(STATUS_MARCHING, 0, 0, u_generation << GENERATION_SHIFT);
    if (info.x != STATUS_MARCHING) {
        if (u_atRest == 0 || (info.w & FLAG_COARSE_HIT) == 0) {
            // At rest a colour reused from the previous view is shaded exactly once (viewport_shade.comp).
            if (u_atRest != 0 && (info.w & FLAG_REUSED) != 0 && (info.w & FLAG_SHADED_NOW) == 0) appendToShadeList(px);
            return;
        }
        // At rest a coarse hit marches on to the surface, and is then shaded like any hit.
        info.x = STATUS_MARCHING;
        info.w &= ~(FLAG_COARSE_HIT | FLAG_REUSED);
    }
#endif
    vec4 state = fresh ? vec4(0.0, 0.0, packStepState(initialOmega, STEEPEST_FLOOR), 0.0) : imageLoad(u_rayState, px);
    const bool verifying = false;
    // The carried colour's depth and age (keepsCarriedColour asks only for a carried centre sample).
    // sampleColor.a is kept with whatever colour the pixel gets (a fresh ray carries none: -1).
    float sampleDepth = fresh ? -1.0 : imageLoad(u_sampleColor, px).a;
    bool carries = info.z == 0 && (info.w & FLAG_CARRIED) != 0;
    float tCarried = carries ? sampleDepth : 0.0;
    float carryAge = carries ? imageLoad(u_centre, px).z : 0.0;
#endif
    int sampleIndex = info.z;
    vec3 rd = cameraRay(vec2(px) + 0.5 + aaJitter(sampleIndex));
    lensSampleRay(px, sampleIndex, ro, rd);
    vec2 stepState = unpackStepState(state.z);
    MarchState s = MarchState(state.x, state.y, stepState.x, MARCH_MARCHING, info.y, 1e30, stepState.y);
    float covered = state.w;
    float deEvals = 0.0;
    bool marchedToHit = false;  // a hit of the marcher, not of the out-of-steps rule
    // A ray that may keep a carried colour may stop at a coarse hit (viewport_common.glsl).
    bool mayStopCoarse = sampleIndex == 0 && (info.w & FLAG_CARRIED) != 0 && u_coarseHits != 0 && u_atRest == 0;
    float tStart, tEnd;
    int i = 0, budget = 0;  // steps taken here, of the frame's budget
    if (!clipCameraRay(ro, rd, tStart, tEnd)) {
        // Misses the bound sphere: nothing anywhere along it.
        s.status = MARCH_ESCAPED;
        s.t = parkedDistance(length(ro), u_boundRadius);
    } else {
        s.t = max(s.t, tStart);
        covered = max(covered, tStart);
        float tanHalf = HALF_DIAGONAL * u_pixelAngle;
#if FROM_LIST
        budget = int(ml_entries[entry].y);
        int stepsHere = budget;
#else
        // The verifying DE does not count against this frame's budget.
        budget = verifying ? 1 + min(u_stepsPerFrame, u_maxSteps - 1) : min(u_stepsPerFrame, u_maxSteps - s.steps);
        int stepsHere = u_deferAfter;
#endif
        for (; i < budget && i < stepsHere && s.status == MARCH_MARCHING; ++i) {
            float t0 = s.t;
            // The last accepted step went omega * lastD from a point whose DE was lastD: up to
            // lastD past that point the ray is certainly in front of any surface.
            float tSafe = s.t - (s.omega - 1.0) * s.lastD;
            if (mayStopCoarse && s.lastD > 0.0 &&
                isCoarseHit(s.lastD, tSafe, info, carryAge, tCarried, u_maxCarryFrames, u_detail, px)) {
                s.t = tSafe;
                s.omega = 1.0;  // resumes (at rest) with plain steps from here
                s.status = MARCH_HIT;
                info.w |= FLAG_COARSE_HIT;
                break;
            }
            if (s.t > tEnd) {  // beyond the bound sphere nothing is left to find
                s.status = MARCH_ESCAPED;
                break;
            }
            marchSteps(ro, rd, tEnd, u_pixelAngle, 1, s, deEvals);
#if START
            if (verifying) {
                // The first step of a reprojected start verifies it: a start within the hit
                // threshold of a surface may lie behind a thin shell, so the ray restarts.
                verifying = false;
                if (s.status == MARCH_HIT) {
                    s = MarchState(start.restartAt, 0.0, initialOmega, MARCH_MARCHING, 0, 1e30, STEEPEST_FLOOR);
                    budget = i + 1 + min(u_stepsPerFrame, u_maxSteps);
                } else {
                    covered = t0;  // reprojection vouches for the cone up to the start
                    reprojected = true;
                }
                continue;
            }
#endif
            // An accepted step stored the DE at t0 in lastD (a fallback step moves t backward).
            if (sampleIndex == 0 && s.status == MARCH_MARCHING && s.t > t0)
                covered = extendConeCoverage(covered, t0, s.lastD, tanHalf);
        }
        marchedToHit = s.status == MARCH_HIT;
        // Out of steps: as the still renderer (still.frag), a ray crawling along a grazing surface
        // is a hit; anything else is background. (With i < budget the ray has steps left, on the
        // march list.)
        if (s.status == MARCH_MARCHING && i == budget && s.steps >= u_maxSteps)
            s.status = countsAsHit(s, u_pixelAngle) ? MARCH_HIT : MARCH_ESCAPED;
    }
    if (s.status == MARCH_ESCAPED && s.t > tEnd) s.t = parkedDistance(length(ro), u_boundRadius);
    info.x = s.status;
    // A coarse hit keeps its carried colour (isCoarseHit asked). Any other hit that does not keep
    // it is shaded, and a marched one is refined (march.glsl) first, in the shade pass: refining
    // here would cost every pixel the refinement's DE code (llvmpipe, above).
    bool keeps = (info.w & FLAG_COARSE_HIT) != 0 ||
                 keepsCarriedColour(u_atRest, info, carryAge, s.t, tCarried, u_maxCarryFrames, u_detail, px);
    atomicAdd(c_deEvals, uint(deEvals));
#if START
    vec4 sampleColor = start.carried;
    vec4 colourPoint = start.colourPoint;
#endif
    if (s.status == MARCH_ESCAPED) {
#if START
        sampleColor.rgb = shadeBackground(rd);
        colourPoint = vec4(0.0);
#endif
        info.w = (info.w & ~FLAG_REUSED) | FLAG_SHADED_NOW;
    } else if (s.status == MARCH_HIT && keeps) {
        info.w |= FLAG_REUSED | FLAG_SHADED_NOW;  // sampleColor holds the carried colour
    } else if (s.status == MARCH_HIT) {
        info.w = (info.w & ~FLAG_REUSED) | FLAG_NEEDS_SHADE | (marchedToHit ? FLAG_NEEDS_REFINE : 0);
        appendToShadeList(px);
    }
    // Still marching with budget left: the rest of the frame's steps are the march list's.
    if (s.status == MARCH_MARCHING && i < budget) appendToMarchList(px, budget - i);
    info.y = s.steps;
    imageStore(u_rayState, px, vec4(s.t, s.lastD, packStepState(s.omega, s.steepest), covered));
    imageStore(u_rayInfo, px, info);
#if START
    imageStore(u_sampleColor, px, sampleColor);
    imageStore(u_colourPoint, px, colourPoint);
    imageStore(u_centre, px, vec4(s.t, float(s.status), carryAge, float(u_generation)));
    if (reprojected) atomicAdd(c_reprojected, 1u);  // the others restarted (Viewport::render counts them)
#else
    // One store each, whichever case writes it (llvmpipe pays every store for every pixel).
    bool escaped = s.status == MARCH_ESCAPED;
    if (escaped || fresh)
        imageStore(u_sampleColor, px, escaped ? vec4(shadeBackground(rd), sampleDepth) : vec4(0.0, 0.0, 0.0, -1.0));
    if ((escaped && sampleIndex == 0) || fresh) imageStore(u_colourPoint, px, vec4(0.0));
    if (sampleIndex == 0)
        imageStore(u_centre, px,
                   vec4(s.t, float(s.status), fresh ? 0.0 : imageLoad(u_centre, px).z, float(u_generation)));
#endif
}
