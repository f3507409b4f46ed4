// shaders/viewport_common.glsl — shared by the viewport passes (core/viewport/*): the per-pixel
// march state layout, the camera rays, and the GLSL mirrors of core/viewport/frame_logic.cpp.
// Image rows count from the top (row 0 = first row of a PNG), like shaders/still.frag.
//
// Per-pixel state (all images u_size):
//   rayState    rgba32f  t, lastD of the current sample's ray (march.glsl's MarchState); z: its
//                        omega and steepest, two halves (packStepState); w: cone coverage of
//                        the centre ray (start distance of the AA samples)
//   rayInfo     rgba32i  status (MARCH_*), steps, AA sample index, FLAG_* bits
//   sampleColor rgba32f  rgb: the current sample's colour (or the colour carried by reprojection);
//                        a: distance of the carried colour's point from the camera (-1: none)
//   accum       rgba32f  rgb: sum of the finished samples' colours; a: their count
//   image       rgba32f  the scene-linear result shown (accum mean, carried colour, or the old image)
//   centre      rgba32f  x: t of the sample-0 (pixel centre) ray; y: its status; z: carry age, the
//                        frames its colour has been carried by reprojection without a fresh
//                        shade (0: shaded for this view). Reprojection reads it.
//   colourPoint rgba32f  xyz: the world point the pixel's sample-0 colour is the shading of (a
//                        carried colour keeps its own); w: 1 for a surface colour, 0 otherwise
//   shown       rgba32f  the image displayed and read back (viewport_resolve.comp)
//
// The per-pixel passes run in 32x8 work groups (each shader's local_size, which
// gl::dispatchOver reads back). llvmpipe runs a work group as one task of its thread pool, 8
// lanes at a time, so larger groups share each task's set-up among more pixels: against 8x8,
// 32x8 made the Mandelbulb orbit at 640x360 ~17 % faster (march 71 -> 61 ms, accumulate 18 -> 11,
// resolve 11 -> 9; median of 3-5 runs side by side), and 64x8 or 128x8 gained little more. 256
// invocations is also a size a GPU runs well without limiting the march shader's registers.
// rayState.z: a ray's omega and steepest fall (MarchState), both exact in half precision
// (march.glsl's quantizedOmega and quantizedSteepest), as two halves of one float's bits. steepest,
// the high half, lies in [2^-13, 2^13], so the float is normal: never a NaN pattern, never a
// denormal a driver might flush to 0. (The accumulate pass, which has no march.glsl, stores
// STEEPEST_FLOOR's value 2^-13 and an omega the CPU quantized.)
float packStepState(float omega, float steepest) { return uintBitsToFloat(packHalf2x16(vec2(omega, steepest))); }
vec2 unpackStepState(float stored) { return unpackHalf2x16(floatBitsToUint(stored)); }

uniform ivec2 u_size;
uniform vec3 u_cameraPosition, u_cameraRight, u_cameraUp, u_cameraForward;
uniform float u_tanHalfFovY;
uniform float u_pixelAngle;  // 2 tan(fovY / 2) / height: a pixel's footprint per unit distance

const int STATUS_MARCHING = 0, STATUS_HIT = 1, STATUS_ESCAPED = 2;  // march.glsl's MARCH_*
const int FLAG_NEEDS_SHADE = 1;  // the sample finished marching and has no colour yet
const int FLAG_CARRIED = 2;      // sampleColor holds the colour of a reprojected hit (tCarried in .a)
const int FLAG_REUSED = 4;       // the sample's colour is the carried one, not shaded for this view
const int FLAG_SHADED_NOW = 8;   // shaded this frame, not yet accumulated
const int FLAG_COARSE_HIT = 16;  // a hit that stopped short of the surface under motion (isCoarseHit)
const int FLAG_NEEDS_REFINE = 32; // a marched hit the shade pass refines first (rayState.y: the DE there)
// The view a pixel's ray belongs to: rayInfo.w's bits from GENERATION_SHIFT up and centre.w hold
// the generation of the view it was started in (Viewport::render numbers each new view, from 1).
// A sliced reset starts no ray: each starts when its slice first comes (viewport_march.comp), and
// until then its state is the previous view's, which the reprojection leaves alone.
const int GENERATION_SHIFT = 16;
uniform int u_generation;

// Frame statistics (core/viewport/gpu_counters.cpp reads them back). Each atomicAdd in a
// full-screen pass costs every pixel (llvmpipe loops over the SIMD lanes, active or not), so what
// can be derived is: on a new view, the pixels that restarted are those not reprojected.
layout(std430, binding = 0) buffer ViewportCounters {
    uint c_deEvals, c_reprojected, c_converged, c_shaded, c_busy;
    uint c_shadeDeEvals;  // the part of c_deEvals spent shading (normals, albedo, AO, shadows)
};

// The pixels to shade this frame, appended by the march pass and shaded by an indirect dispatch
// of 64-wide groups (MarchState::shadeList, core/viewport/shade_pass.cpp): on a SIMD CPU rasteriser (llvmpipe) a
// full-screen shading dispatch where ~1% of pixels shade runs each shaded pixel with its SIMD
// neighbours idle; a compacted list keeps every lane busy. groupsX counts the groups the list
// needs (set from the count by viewport_list_groups.comp); groupsY and groupsZ stay 1.
const uint SHADE_GROUP = 64u;
layout(std430, binding = 2) buffer ShadeList {
    uint sl_groupsX, sl_groupsY, sl_groupsZ, sl_count;
    uint sl_pixels[];
};

void appendToShadeList(ivec2 px) {
    sl_pixels[atomicAdd(sl_count, 1u)] = uint(px.y * u_size.x + px.x);
}

// The rays the full-screen march pass left marching with steps of the frame's budget left, for
// the march pass's FROM_LIST variant (viewport_march.comp: why): x the pixel index, y the steps
// left. The header is the shade list's, for an indirect dispatch of SHADE_GROUP-wide groups.
layout(std430, binding = 3) buffer MarchList {
    uint ml_groupsX, ml_groupsY, ml_groupsZ, ml_count;
    uvec2 ml_entries[];
};

void appendToMarchList(ivec2 px, int stepsLeft) {
    ml_entries[atomicAdd(ml_count, 1u)] = uvec2(px.y * u_size.x + px.x, stepsLeft);
}

// The pixel of a list entry's index.
ivec2 listedPixel(uint index) { return ivec2(int(index) % u_size.x, int(index) / u_size.x); }

// Sliced refinement (core/viewport/march_pass.cpp, dispatchOverSlice): a pass dispatched in one
// dimension over the tiles of a slice, a workgroup a tile. The view's tiles are its workgroups
// numbered row by row; the slice holds those whose number modulo sliceCount is sliceIndex, and
// workgroup k of the dispatch is the slice's k-th. With sliceCount 1 the dispatch covers the view.
// `group`: the caller's gl_WorkGroupSize.xy (declared after this file).
ivec2 slicePixel(int sliceCount, int sliceIndex, ivec2 group) {
    int tilesX = (u_size.x + group.x - 1) / group.x;
    int k = int(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x);  // rows of groups past the count limit
    int tile = k * sliceCount + sliceIndex;
    return ivec2(tile % tilesX, tile / tilesX) * group + ivec2(gl_LocalInvocationID.xy);
}

// Mirror of fraktal::viewport::aaJitter (R2 sequence, Roberts 2018).
vec2 aaJitter(int sampleIndex) {
    if (sampleIndex <= 0) return vec2(0.0);
    const float g = 1.32471795724474602596;
    return fract(0.5 + vec2(1.0 / g, 1.0 / (g * g)) * float(sampleIndex)) - 0.5;
}

// The ray through an image position in pixels from the top-left corner (as Camera::rayDirection).
vec3 cameraRay(vec2 imagePos) {
    float aspect = float(u_size.x) / float(u_size.y);
    float ndcX = 2.0 * imagePos.x / float(u_size.x) - 1.0;
    float ndcY = 1.0 - 2.0 * imagePos.y / float(u_size.y);
    return projectionRay(ndcX, ndcY, aspect, u_cameraRight, u_cameraUp, u_cameraForward, u_tanHalfFovY, u_halfFovY,
                         u_projection);
}

// Where a world point lies in the image of a camera (position, basis, tan of half the vertical
// field of view, half of it in radians, projection): pixels from the top-left corner, the inverse
// of cameraRay. t is its distance from the camera. False when the camera does not see it.
// `size`: the image's size in pixels (reprojection into a grid of another size passes its own).
bool projectToImageOfSize(vec3 world, vec3 position, vec3 right, vec3 up, vec3 forward, float tanHalfFovY,
                          float halfFovY, int projection, ivec2 size, out vec2 imagePos, out float t) {
    vec3 v = world - position;
    t = length(v);
    imagePos = vec2(-1.0);
    vec2 ndc;
    if (!projectDirection(v, right, up, forward, tanHalfFovY, halfFovY, projection, float(size.x) / float(size.y), ndc))
        return false;
    imagePos = vec2(0.5 * (ndc.x + 1.0) * float(size.x), 0.5 * (1.0 - ndc.y) * float(size.y));
    return true;
}

bool projectToImage(vec3 world, vec3 position, vec3 right, vec3 up, vec3 forward, float tanHalfFovY,
                    out vec2 imagePos, out float t) {
    return projectToImageOfSize(world, position, right, up, forward, tanHalfFovY, u_halfFovY, u_projection, u_size,
                                imagePos, t);
}

// Mirror of fraktal::viewport::extendConeCoverage (the seed's conservative stop, 4.1).
float extendConeCoverage(float covered, float t, float d, float tanHalfAngle) {
    if (tanHalfAngle >= 1.0 || d <= 0.0) return covered;
    float nearEnd = (t - d) / (1.0 - tanHalfAngle);
    float farEnd = (t + d) / (1.0 + tanHalfAngle);
    if (nearEnd > covered || farEnd <= covered) return covered;
    return farEnd;
}

// Mirror of fraktal::viewport::reprojectionMargin.
float reprojectionMargin(float t, float pixelAngle, float detail) { return 2.0 * pixelAngle * t * max(detail, 1.0); }

// Mirror of fraktal::viewport::parkedDistance.
float parkedDistance(float cameraDistance, float boundRadius) { return cameraDistance + 2.0 * boundRadius; }

// pcg3d (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 9(3), 2020), to [0, 1).
// Mirror of fraktal::viewport::hash01.
float hash01(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return float(v.x >> 8u) / 16777216.0;
}

// Mirror of fraktal::viewport::carriedColourExpires (why: there).
bool carriedColourExpires(int carryAge, int maxCarryFrames, ivec2 px) {
    if (carryAge <= maxCarryFrames - maxCarryFrames / 4) return false;
    if (carryAge > maxCarryFrames) return true;
    return hash01(uvec3(px, uint(carryAge))) * float(maxCarryFrames - carryAge + 2) < 1.0;
}

// Whether a finished sample keeps the colour reprojection carried to its pixel instead of being
// shaded (viewport_shade.comp; the march pass asks first, to skip refining such hits): only under
// motion, only the centre sample, only until the colour expires (specular and fog depend on the
// view), and only when the ray hit where the colour's point lies.
bool keepsCarriedColour(int atRest, ivec4 info, float carryAge, float t, float tCarried, int maxCarryFrames,
                        float detail, ivec2 px) {
    return atRest == 0 && info.x == STATUS_HIT && (info.w & FLAG_CARRIED) != 0 && info.z == 0 &&
           !carriedColourExpires(int(carryAge), maxCarryFrames, px) &&
           abs(t - tCarried) <= reprojectionMargin(tCarried, u_pixelAngle, detail);
}

// Under motion, a ray that keeps a carried colour need not reach the hit threshold: it stops at
// the first point within the reprojection margin of a surface (DE d < margin) whose depth matches
// the carried colour's point as keepsCarriedColour asks. What it shows is the carried colour, and
// its depth stays in front of the surface, which only makes the next frame's start more
// conservative. Marching on to the hit threshold (detail footprints, half a pixel by default, from
// a start two footprints in front of the nearest of 4x4 points) cost 3-4 more DE per such pixel
// per frame on the fold fractals. The price: a ray passing within the margin of a thin part or a
// silhouette keeps that part's colour where a full march would have gone past it and shaded what
// lies behind, so thin parts look up to the margin thicker while the camera moves (bench/README.md
// has the error this costs). At rest a coarse hit marches on to the surface
// (viewport_march.comp), and is refined and shaded exactly.
bool isCoarseHit(float d, float t, ivec4 info, float carryAge, float tCarried, int maxCarryFrames, float detail,
                 ivec2 px) {
    return d < reprojectionMargin(t, u_pixelAngle, detail) &&
           keepsCarriedColour(0, ivec4(STATUS_HIT, info.yzw), carryAge, t, tCarried, maxCarryFrames, detail, px);
}

// Half the diagonal of a pixel, as an angle: every AA sample of a pixel lies in this cone.
const float HALF_DIAGONAL = 0.70710678;

// Depth of field (shaders/lens.glsl): anti-aliasing sample `sampleIndex` > 0 of pixel `px` leaves
// its own point of the aperture, the Halton (2, 3) point of its index shifted per pixel
// (Cranley-Patterson) so that neighbouring pixels' noise does not line up. Sample 0, the pixel-centre
// ray that reprojection carries, stays a pinhole ray.
void lensSampleRay(ivec2 px, int sampleIndex, inout vec3 ro, inout vec3 rd) {
    if (sampleIndex <= 0 || u_apertureRadius <= 0.0) return;
    vec2 shift = vec2(hash01(uvec3(px, 0x6c656e73u)), hash01(uvec3(px, 0x6170u)));
    vec2 u = fract(shift + vec2(radicalInverse(sampleIndex, 2), radicalInverse(sampleIndex, 3)));
    thinLensRay(ro, rd, u_cameraForward, u_cameraRight, u_cameraUp, u.x, u.y);
}
