// shaders/viewport_accumulate.comp — progressive anti-aliasing (seed 4.1): adds each newly shaded
// sample to the pixel's running mean and, while the camera rests (AT_REST 1), starts the pixel's
// next jittered sample. The new ray starts at the centre ray's cone coverage (the conservative
// stop): every ray inside the pixel is free of surface up to there, so it still finds its own
// first hit and silhouettes get truly anti-aliased. Under motion (AT_REST 0) it finds where the
// pixel's one sample lies for the resolve pass's reconstruction (u_samplePosition), once per
// pixel rather than once per neighbour that reads it (9 projections per pixel cost 15 of the
// resolve's 28 ms at 640x360 on llvmpipe). Writes the scene-linear image. Needs
// viewport_common.glsl.
layout(local_size_x = 32, local_size_y = 8) in;  // viewport_common.glsl: why 32x8
layout(rgba32f) uniform image2D u_rayState;
layout(rgba32i) uniform iimage2D u_rayInfo;
layout(rgba32f) uniform image2D u_sampleColor;
layout(rgba32f) uniform image2D u_accum;
layout(rgba32f) uniform image2D u_image;
layout(rgba32f) uniform image2D u_centre;
#if !AT_REST
layout(rgba32f) uniform image2D u_samplePosition;
layout(rgba32f) uniform image2D u_colourPoint;

// Where a pixel's sample lies in the image (pixels from the top-left) and how far its surface is:
// a surface colour lies at its own point; a background colour at the pixel centre, infinitely far.
// False when the pixel has no sample for this view yet (its ray is marching and nothing was carried).
bool sampleOf(ivec2 q, ivec4 info, out vec2 position, out float depth) {
    vec4 point = imageLoad(u_colourPoint, q);
    position = vec2(q) + 0.5;
    depth = 1e30;
    if (info.x == STATUS_MARCHING && (info.w & FLAG_CARRIED) == 0) return false;
    if (point.w == 0.0) return info.x != STATUS_MARCHING;  // background (or a colour of unknown point)
    return projectToImage(point.xyz, u_cameraPosition, u_cameraRight, u_cameraUp, u_cameraForward, u_tanHalfFovY,
                          position, depth);
}
#endif
uniform int u_maxSamples;
uniform float u_initialOmega;
// Sliced refinement (viewport_march.comp): dispatched over the tiles of the frame's slice alone,
// the only pixels the frame changed; 1: the whole view.
uniform int u_sliceCount;
uniform int u_sliceIndex;

void main() {
    ivec2 px = slicePixel(u_sliceCount, u_sliceIndex, ivec2(gl_WorkGroupSize.xy));
    if (any(greaterThanEqual(px, u_size))) return;
    ivec4 info = imageLoad(u_rayInfo, px);
    vec4 accum = imageLoad(u_accum, px);
    bool changed = false;
    if ((info.w & FLAG_SHADED_NOW) != 0) {
        vec3 color = imageLoad(u_sampleColor, px).rgb;
        // Sample 0 replaces: it is the first sample, or the exact shade of a reused colour. With a
        // thin lens sample 1, the first through the lens, replaces the pinhole sample 0 in turn.
        bool replaces = info.z == 0 || (info.z == 1 && u_apertureRadius > 0.0);
        accum = replaces ? vec4(color, 1.0) : accum + vec4(color, 1.0);
        info.w &= ~FLAG_SHADED_NOW;
        imageStore(u_accum, px, accum);
        imageStore(u_image, px, vec4(accum.rgb / accum.a, 1.0));
        changed = true;
    }
    bool idle = info.x != STATUS_MARCHING && (info.w & (FLAG_NEEDS_SHADE | FLAG_REUSED)) == 0;
#if AT_REST
    if (idle && info.z + 1 < u_maxSamples) {  // AASchedule::next
        // The centre ray's empty cone says nothing about a ray from another point of the lens.
        float start = u_apertureRadius > 0.0 ? 0.0 : imageLoad(u_rayState, px).w;
        imageStore(u_rayState, px, vec4(start, 0.0, packStepState(u_initialOmega, 1.0 / 8192.0), start));
        info = ivec4(STATUS_MARCHING, 0, info.z + 1, info.w);
        changed = true;
        idle = false;
    }
#else
    vec2 position;
    float depth;
    bool sampled = sampleOf(px, info, position, depth);
    imageStore(u_samplePosition, px, vec4(position, depth, sampled ? 1.0 : 0.0));
#endif
    if (changed) imageStore(u_rayInfo, px, info);
    if (imageLoad(u_centre, px).y != float(STATUS_MARCHING)) atomicAdd(c_converged, 1u);
    if (!idle) atomicAdd(c_busy, 1u);
}
