// shaders/viewport_resolve.comp — the image shown (MarchState::shown) from the scene-linear samples
// (MarchState::image) under camera motion (at rest, or with the filter off, it is a copy of the
// image: runResolvePass). Under camera motion each pixel holds one sample, and a reprojected one
// lies where its own surface point projects, anywhere in the pixel (viewport_reproject.comp), so
// neighbouring samples fall at scattered positions around the pixel centre. The shown colour is
// then a reconstruction from every sample of the 3x3 neighbourhood within u_radius pixels of
// the centre, tent-weighted by distance, on the same surface as the pixel's own sample: a better
// estimate of the pixel's anti-aliased value than any single sample. At the default radius of one
// pixel, samples all on the pixel grid (restarting every ray) are left as they are: only the
// pixel's own sample is nearer than a pixel. Needs viewport_common.glsl.
layout(local_size_x = 32, local_size_y = 8) in;  // viewport_common.glsl: why 32x8
layout(rgba32f) uniform image2D u_image;
// Where each pixel's sample lies (xy, pixels from the top-left) and its depth (z, 1e30 for the
// background); w: 0 when the pixel has no sample for this view yet (viewport_accumulate.comp).
layout(rgba32f) uniform image2D u_samplePosition;
layout(rgba32f) uniform writeonly image2D u_shown;

uniform float u_radius;  // pixels: the tent's radius (ViewportOptions::motionFilterRadius)

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, u_size))) return;
    vec4 own = imageLoad(u_image, px);
    vec4 ownSample = imageLoad(u_samplePosition, px);
    if (ownSample.w == 0.0) {
        imageStore(u_shown, px, own);
        return;
    }
    float ownDepth = ownSample.z;
    vec2 centre = vec2(px) + 0.5;
    float sameSurface = ownDepth < 1e30 ? reprojectionMargin(ownDepth, u_pixelAngle, 1.0) : 0.0;
    vec3 sum = vec3(0.0);
    float weightSum = 0.0;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            ivec2 q = px + ivec2(dx, dy);
            if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, u_size))) continue;
            vec4 neighbour = imageLoad(u_samplePosition, q);
            if (neighbour.w == 0.0) continue;
            vec2 position = neighbour.xy;
            float depth = neighbour.z;
            bool bothBackground = depth >= 1e30 && ownDepth >= 1e30;
            if (!bothBackground && abs(depth - ownDepth) > sameSurface) continue;
            float w = max(0.0, 1.0 - length(position - centre) / u_radius);
            sum += w * imageLoad(u_image, q).rgb;
            weightSum += w;
        }
    imageStore(u_shown, px, weightSum > 0.0 ? vec4(sum / weightSum, 1.0) : own);
}
