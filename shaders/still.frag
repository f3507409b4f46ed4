// shaders/still.frag — the offline still renderer: one tile of the image per draw. Needs the
// formula, shaders/march.glsl, shaders/shade.glsl and shaders/lens.glsl before it.
//
// Depth of field: with a thin lens (u_apertureRadius > 0, shaders/lens.glsl) each sample's ray
// leaves its own point of the aperture, so the pixel's samples average over the lens as the path
// tracer's do; the pixel-centre sample is then no pinhole ray, and the CPU reference (a pinhole)
// is compared only without a lens.
//
// Each pixel takes u_spp camera rays. Sample positions are importance-sampled from the
// reconstruction filter (a separable Blackman-Harris window of radius u_filterRadius pixels,
// its inverse CDF tabulated on the CPU, core/render/filter.cpp), so all samples weigh the same
// (pbrt-v4's FilterSampler idea). The 2D points are Roberts' R2 low-discrepancy sequence with a
// per-pixel random rotation (Cranley-Patterson), seeded by the pixel's image coordinates so that
// tiles do not show. One sample per pixel goes through the pixel centre (the CPU reference does too).
//
// Adaptive sampling: a pixel stops early once its samples agree. After ADAPTIVE_MIN_SAMPLES
// samples, and after each one from then on, it stops when every sample so far has the same
// coverage (all hit or all missed), none of them lies near a silhouette, and the spread of their
// colours, max - min per channel of sqrt(colour) (roughly perceptual), is within
// u_adaptiveTolerance. Flat sky and smooth surfaces stop at the minimum; edges and sub-pixel
// detail, where samples disagree, take all u_spp. The test is conservative in the sense of
// Mitchell's adaptive sampling ("Generating antialiased images at low sampling densities",
// SIGGRAPH 1987): a contrast test on the samples taken, never on fewer than two. Agreement alone
// misses thin coverage: where the object covers a tenth of the filter's footprint, two samples
// both miss it four times in five, and a silhouette pixel stopped at 0 (16 adaptive samples had
// the coverage error of 4 fixed ones, bench/stills/equal_quality.sh). So the distance estimate
// says where an edge may be: a missed ray that passed within the footprint's width of the surface
// (its smallest d / t, the half-angle of an empty cone about the ray), or a hit at a grazing angle,
// keeps the pixel sampling. u_adaptiveTolerance = 0 turns it off.
//
// Framebuffer row j of a tile is image row u_tileOrigin.y + j, counted from the top, so a
// glReadPixels of the tile gives the image's rows in file order.
//
// Uniforms:
//   ivec2 u_imageSize, u_tileOrigin      full image size; this tile's top-left pixel
//   vec3  u_cameraPosition, u_cameraRight, u_cameraUp, u_cameraForward   orthonormal camera frame
//   float u_tanHalfFovY                  tan(vertical field of view / 2)
//   int   u_spp, u_maxSteps              samples per pixel; march steps per camera ray
//   float u_filterRadius                 filter radius in pixels
//   float u_filterInverseCdf[FILTER_TABLE_SIZE]   inverse CDF of the 1D filter over [0, 1]
//   int   u_transparentBackground        1: background contributes nothing (premultiplied RGBA)
//   float u_adaptiveTolerance            spread of sqrt(colour) under which a pixel stops (0: off)
#define FILTER_TABLE_SIZE 65
#define ADAPTIVE_MIN_SAMPLES 2
#define GRAZING_COSINE 0.2
uniform ivec2 u_imageSize;
uniform ivec2 u_tileOrigin;
uniform vec3 u_cameraPosition, u_cameraRight, u_cameraUp, u_cameraForward;
uniform float u_tanHalfFovY;
uniform int u_spp;
uniform int u_maxSteps;
uniform float u_filterRadius;
uniform float u_filterInverseCdf[FILTER_TABLE_SIZE];
uniform int u_transparentBackground;
uniform float u_adaptiveTolerance;

layout(location = 0) out vec4 outColor;       // scene-linear RGB, alpha = coverage
layout(location = 1) out vec4 outNormalDepth; // world normal (coverage-weighted), depth: nearest hit
layout(location = 2) out vec4 outAlbedoAO;    // orbit-trap albedo, ambient occlusion (coverage-weighted)
layout(location = 3) out vec4 outStats;       // DE evaluations / u_spp, march steps per ray, samples taken

uint hashPixel(uvec2 p) {  // PCG-style integer hash (Jarzynski and Olano 2020)
    uint v = p.x * 1664525u + p.y * 22695477u + 1013904223u;
    v = v * 747796405u + 2891336453u;
    uint word = ((v >> ((v >> 28u) + 4u)) ^ v) * 277803737u;
    return (word >> 22u) ^ word;
}

float filterOffset(float u) {
    float x = clamp(u, 0.0, 1.0) * float(FILTER_TABLE_SIZE - 1);
    int i = min(int(x), FILTER_TABLE_SIZE - 2);
    return mix(u_filterInverseCdf[i], u_filterInverseCdf[i + 1], x - float(i)) * u_filterRadius;
}

void main() {
    ivec2 pixel = u_tileOrigin + ivec2(gl_FragCoord.xy);
    if (pixel.x >= u_imageSize.x || pixel.y >= u_imageSize.y) discard;
    float aspect = float(u_imageSize.x) / float(u_imageSize.y);
    float pixelAngle = projectionPixelAngle(u_tanHalfFovY, u_halfFovY, u_projection, u_imageSize);
    uint h = hashPixel(uvec2(pixel));
    vec2 rotation = vec2(float(h & 0xffffu), float(h >> 16u)) / 65536.0;
    uint hLens = hashPixel(uvec2(h, 0x9e3779b9u));
    vec2 lensRotation = vec2(float(hLens & 0xffffu), float(hLens >> 16u)) / 65536.0;

    vec3 color = vec3(0.0), normal = vec3(0.0), albedo = vec3(0.0);
    float coverage = 0.0, ao = 0.0, depth = 1e30, deEvals = 0.0, shadeEvals = 0.0, steps = 0.0;
    int spp = max(u_spp, 1);
    vec3 sampleMin = vec3(1e30), sampleMax = vec3(-1e30);
    int taken = 0;
    bool nearEdge = false;
    for (int k = 0; k < spp; ++k) {
        vec2 offset = vec2(0.0);
        if (spp > 1) {
            vec2 u = fract(rotation + float(k) * vec2(0.7548776662466927, 0.5698402909980532));
            offset = vec2(filterOffset(u.x), filterOffset(u.y));
        }
        vec2 imagePos = vec2(pixel) + 0.5 + offset;
        float ndcX = 2.0 * imagePos.x / float(u_imageSize.x) - 1.0;
        float ndcY = 1.0 - 2.0 * imagePos.y / float(u_imageSize.y);
        vec3 rd = projectionRay(ndcX, ndcY, aspect, u_cameraRight, u_cameraUp, u_cameraForward, u_tanHalfFovY,
                                u_halfFovY, u_projection);
        vec3 ro = u_cameraPosition;
        // Depth of field: the k-th point of a Halton (2, 3) sequence on the aperture, shifted per
        // pixel (Cranley-Patterson) by a second hash so that it does not follow the filter offset.
        if (u_apertureRadius > 0.0) {
            vec2 lensPoint = fract(lensRotation + vec2(radicalInverse(k, 2), radicalInverse(k, 3)));
            thinLensRay(ro, rd, u_cameraForward, u_cameraRight, u_cameraUp, lensPoint.x, lensPoint.y);
        }

        float tStart, tEnd;
        bool hit = false;
        MarchState s = marchStart(0.0);
        if (clipCameraRay(ro, rd, tStart, tEnd)) {
            s = marchStart(tStart);
            marchRay(ro, rd, tEnd, pixelAngle, u_maxSteps, s, deEvals);
            hit = countsAsHit(s, pixelAngle);
            steps += float(s.steps);
            // The pixel's samples lie within 2 u_filterRadius pixels of each other.
            nearEdge = nearEdge || (!hit && s.closest < 2.0 * u_filterRadius * pixelAngle);
        }
        vec3 sampleColor = vec3(0.0);
        if (hit) {
            float marchEvals = deEvals;
            SurfaceSample surface = shadeSurface(ro + rd * s.t, rd, s.t, pixelAngle, deEvals);
            shadeEvals += deEvals - marchEvals;
            sampleColor = surface.color;
            normal += surface.normal;
            albedo += surface.albedo;
            ao += surface.ao;
            coverage += 1.0;
            depth = min(depth, s.t);
            nearEdge = nearEdge || abs(dot(surface.normal, rd)) < GRAZING_COSINE;
        } else if (u_transparentBackground == 0) {
            sampleColor = shadeBackground(rd);
        }
        color += sampleColor;
        taken = k + 1;
        vec3 perceptual = sqrt(max(sampleColor, vec3(0.0)));
        sampleMin = min(sampleMin, perceptual);
        sampleMax = max(sampleMax, perceptual);
        bool sameCoverage = coverage == 0.0 || coverage == float(taken);
        if (u_adaptiveTolerance > 0.0 && taken >= ADAPTIVE_MIN_SAMPLES && sameCoverage && !nearEdge &&
            all(lessThanEqual(sampleMax - sampleMin, vec3(u_adaptiveTolerance))))
            break;
    }
    float w = 1.0 / float(taken);
    outColor = vec4(color * w, coverage * w);
    outNormalDepth = vec4(normal * w, depth);
    outAlbedoAO = vec4(albedo * w, ao * w);
    // DE evaluations over the nominal spp, so that (this) x spp is the pixel's total, and the part
    // of them spent shading (normals, albedo, AO, shadows, reflections) (bench/stills/de_count.cpp).
    outStats = vec4(deEvals / float(spp), steps * w, float(taken), shadeEvals / float(spp));
}
