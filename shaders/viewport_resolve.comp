// shaders/viewport_resolve.comp — the image shown (MarchState::shown) from the scene-linear
// samples (MarchState::image) under camera motion (at rest, or with the filter off, it is a copy
// of the image: runResolvePass). Under camera motion each pixel holds one sample, and a reprojected one lies where its own surface
// point projects, anywhere in the pixel (viewport_reproject.comp), so neighbouring samples fall
// at scattered positions around the pixel centre. The shown colour is then a reconstruction from
// every sample of the 3x3 neighbourhood within RESOLVE_RADIUS pixels of the centre, tent-weighted
// by distance, on the same surface as the pixel's own sample: a better estimate of the pixel's
// anti-aliased value than any single sample. Samples all on the pixel grid (restarting every ray)
// are left as they are: the radius is under a pixel, so only the pixel's own sample counts.
// Needs viewport_common.glsl.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32i, binding = 1) uniform iimage2D u_rayInfo;
layout(rgba32f, binding = 4) uniform image2D u_image;
layout(rgba32f, binding = 5) uniform image2D u_centre;
layout(rgba32f, binding = 10) uniform image2D u_colourPoint;
layout(rgba32f, binding = 11) uniform writeonly image2D u_shown;

const float RESOLVE_RADIUS = 1.0;  // pixels: the tent of bilinear reconstruction

// Where a pixel's sample lies in the image (pixels from the top-left) and how far its surface is:
// a surface colour lies at its own point; a background colour at the pixel centre, infinitely far.
// False when the pixel has no sample for this view yet (its ray is marching and nothing was carried).
bool sampleOf(ivec2 q, out vec2 position, out float depth) {
    ivec4 info = imageLoad(u_rayInfo, q);
    vec4 point = imageLoad(u_colourPoint, q);
    position = vec2(q) + 0.5;
    depth = 1e30;
    if (info.x == STATUS_MARCHING && (info.w & FLAG_CARRIED) == 0) return false;
    if (point.w == 0.0) return info.x != STATUS_MARCHING;  // background (or a colour of unknown point)
    return projectToImage(point.xyz, u_cameraPosition, u_cameraRight, u_cameraUp, u_cameraForward, u_tanHalfFovY,
                          position, depth);
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, u_size))) return;
    vec4 own = imageLoad(u_image, px);
    vec2 ownPosition;
    float ownDepth;
    if (!sampleOf(px, ownPosition, ownDepth)) {
        imageStore(u_shown, px, own);
        return;
    }
    vec2 centre = vec2(px) + 0.5;
    float sameSurface = ownDepth < 1e30 ? reprojectionMargin(ownDepth, u_pixelAngle, 1.0) : 0.0;
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = px + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, u_size))) continue;
            vec2 position;
            float depth;
            if (!sampleOf(q, position, depth)) continue;
            bool bothBackground = depth >= 1e30 && ownDepth >= 1e30;
            if (!bothBackground && abs(depth - ownDepth) > sameSurface) continue;
            float w = max(0.0, 1.0 - length(position - centre) / RESOLVE_RADIUS);
            sum += w * imageLoad(u_image, q).rgb;
            weightSum += w;
        }
    imageStore(u_shown, px, weightSum > 0.0 ? vec4(sum / weightSum, 1.0) : own);
}
