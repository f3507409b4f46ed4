// shaders/pathtrace.frag — the progressive path tracer: u_samples samples of every pixel per draw,
// added (blending GL_ONE, GL_ONE) to the sums of the draws before. Needs the formula,
// shaders/march.glsl, shaders/shade.glsl and shaders/lens.glsl before it. The estimator and its random numbers are
// those of core/cpu_render/cpu_path_tracer.cpp (its header says what they are), mirrored line for
// line in single precision: change both together.
//
// Uniforms (core/render/path_tracer.cpp):
//   ivec2 u_imageSize; int u_firstSample, u_samples, u_maxSteps, u_transparentBackground, u_writeDepth
//     (1 on the first draw only: the depth is written, not summed)
//   camera: u_cameraPosition/Right/Up/Forward, u_tanHalfFovY; thin lens: u_apertureRadius (0: pinhole),
//     u_focusDistance, u_blades
//   path: u_bounces, u_alpha (GGX), u_f0, u_emission
//   lights: u_lightCount; per light u_lightType (0 directional, 1 sphere, 2 rect), u_lightPower
//     (colour x intensity), u_lightVector (direction or position), u_lightNormal, u_lightUp,
//     u_lightSize (size, rect height, 0)
//   environment: u_envSize (0: none), u_envRotation, u_envTotal, u_envVisible; buffers 0..2 hold
//     its RGB texels, the row CDF and the per-row column CDFs (core/render/environment.hpp)
#define MAX_LIGHTS 16
#define PI 3.14159265358979323846
#define INFINITY 1e30
uniform ivec2 u_imageSize;
uniform int u_firstSample, u_samples, u_maxSteps, u_transparentBackground, u_writeDepth;
uniform vec3 u_cameraPosition, u_cameraRight, u_cameraUp, u_cameraForward;
uniform float u_tanHalfFovY;
uniform int u_bounces;
uniform float u_alpha, u_f0, u_emission;
uniform int u_lightCount;
uniform int u_lightType[MAX_LIGHTS];
uniform vec3 u_lightPower[MAX_LIGHTS], u_lightVector[MAX_LIGHTS], u_lightNormal[MAX_LIGHTS], u_lightUp[MAX_LIGHTS],
    u_lightSize[MAX_LIGHTS];
uniform ivec2 u_envSize;
uniform float u_envRotation, u_envTotal;
uniform int u_envVisible;
layout(std430, binding = 0) readonly buffer EnvRgb { float envRgb[]; };
layout(std430, binding = 1) readonly buffer EnvMarginal { float envMarginal[]; };
layout(std430, binding = 2) readonly buffer EnvConditional { float envConditional[]; };

layout(location = 0) out vec4 outBeauty;
layout(location = 1) out vec4 outDiffuseDirect;
layout(location = 2) out vec4 outDiffuseIndirect;
layout(location = 3) out vec4 outSpecular;
layout(location = 4) out vec4 outEmission;
layout(location = 5) out vec4 outAlbedo;
layout(location = 6) out vec4 outNormalDepth;

uint pathHash(uint v) {
    uint state = v * 747796405u + 2891336453u;
    uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}
uint rngState;
float rng() {
    rngState = pathHash(rngState);
    return float(rngState >> 8u) * (1.0 / 16777216.0);
}

void frameAbout(vec3 n, out vec3 t, out vec3 b) {
    float sgn = n.z >= 0.0 ? 1.0 : -1.0;
    float a = -1.0 / (sgn + n.z);
    float c = n.x * n.y * a;
    t = vec3(1.0 + sgn * n.x * n.x * a, sgn * c, -sgn * n.x);
    b = vec3(c, sgn + n.y * n.y * a, -n.y);
}
vec3 fromFrame(vec3 n, float x, float y, float z) {
    vec3 t, b;
    frameAbout(n, t, b);
    return t * x + b * y + n * z;
}
vec3 sampleCone(vec3 axis, float cosMax, float u1, float u2) {
    float cosTheta = 1.0 - u1 * (1.0 - cosMax);
    float sinTheta = sqrt(max(0.0, 1.0 - cosTheta * cosTheta));
    float phi = 2.0 * PI * u2;
    return fromFrame(axis, sinTheta * cos(phi), sinTheta * sin(phi), cosTheta);
}

float ggxD(float cosH) {
    float a2 = u_alpha * u_alpha;
    float k = cosH * cosH * (a2 - 1.0) + 1.0;
    return a2 / (PI * k * k);
}
float smithG1(float cosV) {
    float a2 = u_alpha * u_alpha;
    return 2.0 * cosV / (cosV + sqrt(a2 + (1.0 - a2) * cosV * cosV));
}
float specularProbability() { return u_f0 > 0.0 ? 0.5 : 0.0; }

void evalBsdf(vec3 albedo, vec3 n, vec3 wo, vec3 wi, out vec3 fd, out vec3 fs) {
    float cosI = dot(n, wi), cosO = dot(n, wo);
    fd = albedo * ((1.0 - u_f0) / PI);
    fs = vec3(0.0);
    if (cosI <= 0.0 || cosO <= 0.0 || u_f0 <= 0.0) return;
    vec3 h = normalize(wi + wo);
    float fresnel = u_f0 + (1.0 - u_f0) * pow(1.0 - clamp(dot(wo, h), 0.0, 1.0), 5.0);
    fs = vec3(fresnel * ggxD(dot(n, h)) * smithG1(cosI) * smithG1(cosO) / (4.0 * cosI * cosO));
}
float bsdfPdf(vec3 n, vec3 wo, vec3 wi) {
    float cosI = dot(n, wi);
    if (cosI <= 0.0) return 0.0;
    float ps = specularProbability();
    float pdf = (1.0 - ps) * cosI / PI;
    if (ps > 0.0) {
        vec3 h = normalize(wi + wo);
        float woh = dot(wo, h);
        if (woh > 0.0) pdf += ps * ggxD(dot(n, h)) * dot(n, h) / (4.0 * woh);
    }
    return pdf;
}
vec3 sampleBsdf(vec3 n, vec3 wo, float uLobe, float u1, float u2) {
    if (uLobe < specularProbability()) {
        float a2 = u_alpha * u_alpha;
        float cosH = sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1));
        float sinH = sqrt(max(0.0, 1.0 - cosH * cosH));
        float phi = 2.0 * PI * u2;
        vec3 h = fromFrame(n, sinH * cos(phi), sinH * sin(phi), cosH);
        return reflect(-wo, h);
    }
    float r = sqrt(u1), phi = 2.0 * PI * u2;
    return fromFrame(n, r * cos(phi), r * sin(phi), sqrt(max(0.0, 1.0 - u1)));
}

// Environment map (core/render/environment.cpp).
float envLuminance(int texel) {
    return 0.2126 * envRgb[texel * 3] + 0.7152 * envRgb[texel * 3 + 1] + 0.0722 * envRgb[texel * 3 + 2];
}
ivec2 envTexel(vec3 d) {
    float phi = atan(d.x, -d.z) - u_envRotation;
    float u = phi / (2.0 * PI) + 0.5;
    u -= floor(u);
    float v = acos(clamp(d.y, -1.0, 1.0)) / PI;
    return ivec2(min(int(u * float(u_envSize.x)), u_envSize.x - 1), min(int(v * float(u_envSize.y)), u_envSize.y - 1));
}
vec3 envRadiance(vec3 d) {
    ivec2 p = envTexel(d);
    int i = (p.y * u_envSize.x + p.x) * 3;
    return vec3(envRgb[i], envRgb[i + 1], envRgb[i + 2]);
}
float envPdf(vec3 d) {
    if (u_envTotal <= 0.0) return 0.0;
    ivec2 p = envTexel(d);
    float sinTheta = sin(PI * (float(p.y) + 0.5) / float(u_envSize.y));
    if (sinTheta <= 0.0) return 0.0;
    float weight = envLuminance(p.y * u_envSize.x + p.x) * sinTheta;
    return weight / u_envTotal * float(u_envSize.x) * float(u_envSize.y) / (2.0 * PI * PI * sinTheta);
}
vec3 envDirection(float u, float v) {
    float phi = (u - 0.5) * 2.0 * PI + u_envRotation;
    float theta = v * PI;
    return vec3(sin(theta) * sin(phi), cos(theta), -sin(theta) * cos(phi));
}
// The i with cdf[i] <= u < cdf[i + 1], cdf = the n + 1 floats at `base` of the marginal (row < 0)
// or of a row's conditional.
int findInterval(int row, int n, float u) {
    int lo = 0, hi = n;  // cdf[lo] <= u, cdf[hi] > u (or hi = n)
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        float c = row < 0 ? envMarginal[mid] : envConditional[row * (n + 1) + mid];
        if (c <= u) lo = mid; else hi = mid;
    }
    return lo;
}
vec3 envSample(float u1, float u2, out float pdf) {
    int y = findInterval(-1, u_envSize.y, u1);
    int x = findInterval(y, u_envSize.x, u2);
    int base = y * (u_envSize.x + 1);
    float dv = (u1 - envMarginal[y]) / max(envMarginal[y + 1] - envMarginal[y], 1e-30);
    float du = (u2 - envConditional[base + x]) / max(envConditional[base + x + 1] - envConditional[base + x], 1e-30);
    vec3 d = envDirection((float(x) + clamp(du, 0.0, 1.0)) / float(u_envSize.x),
                          (float(y) + clamp(dv, 0.0, 1.0)) / float(u_envSize.y));
    pdf = envPdf(d);
    return d;
}
bool envActive() { return u_envSize.x > 0; }
vec3 pathBackground(vec3 rd) { return envActive() ? envRadiance(rd) : shadeBackground(rd); }

float traceSecondary(vec3 ro, vec3 rd, float eps, float maxDistance, inout float deEvals) {
    float tStart, tEnd;
    if (!clipToBound(ro, rd, tStart, tEnd)) return INFINITY;
    tEnd = min(tEnd, maxDistance);
    float t = tStart;
    for (int i = 0; i < u_maxSteps && t < tEnd; ++i) {
        hitThreshold = eps;
        float d = DE(ro + rd * t);
        hitThreshold = 0.0;
        deEvals += 1.0;
        if (d < eps) return t;
        t += d;
    }
    return INFINITY;
}

bool sampleLight(int l, vec3 p, float u1, float u2, out vec3 wi, out vec3 li, out float dist) {
    vec3 power = u_lightPower[l];
    float size = u_lightSize[l].x;
    wi = vec3(0.0);
    li = vec3(0.0);
    dist = INFINITY;
    if (u_lightType[l] == 0) {
        vec3 axis = normalize(u_lightVector[l]);
        wi = size > 0.0 ? sampleCone(axis, cos(size * PI / 180.0), u1, u2) : axis;
        li = power;
        return true;
    }
    if (u_lightType[l] == 1) {
        vec3 toCentre = u_lightVector[l] - p;
        float d = length(toCentre);
        if (d <= size || d <= 0.0) return false;
        if (size <= 0.0) {
            wi = toCentre / d;
            li = power / (d * d);
            dist = d;
            return true;
        }
        float sinMax2 = size * size / (d * d);
        float cosMax = sqrt(max(0.0, 1.0 - sinMax2));
        wi = sampleCone(toCentre / d, cosMax, u1, u2);
        float b = dot(toCentre, wi);
        dist = b - sqrt(max(0.0, b * b - (d * d - size * size)));
        li = power / (PI * size * size) * (2.0 * PI * (1.0 - cosMax));
        return true;
    }
    vec3 n = normalize(u_lightNormal[l]);
    vec3 up = normalize(u_lightUp[l] - n * dot(n, u_lightUp[l]));
    vec3 right = cross(up, n);
    float height = u_lightSize[l].y;
    vec3 q = u_lightVector[l] + right * ((u1 - 0.5) * size) + up * ((u2 - 0.5) * height);
    vec3 toQ = q - p;
    dist = length(toQ);
    if (dist <= 0.0) return false;
    wi = toQ / dist;
    float cosLight = -dot(n, wi);
    if (cosLight <= 0.0) return false;
    li = power * (size * height * cosLight / (dist * dist));
    return true;
}

void main() {
    ivec2 pixel = ivec2(gl_FragCoord.xy);
    pixel.y = u_imageSize.y - 1 - pixel.y;  // framebuffer row 0 is the image's bottom row
    float aspect = float(u_imageSize.x) / float(u_imageSize.y);
    float pixelAngle = projectionPixelAngle(u_tanHalfFovY, u_halfFovY, u_projection, u_imageSize);
    vec3 sumBeauty = vec3(0.0), sumDiffuseDirect = vec3(0.0), sumDiffuseIndirect = vec3(0.0),
         sumSpecular = vec3(0.0), sumEmission = vec3(0.0), sumAlbedo = vec3(0.0), sumNormal = vec3(0.0);
    float coverage = 0.0, deEvals = 0.0;
    for (int k = 0; k < u_samples; ++k) {
        rngState = pathHash(uint(pixel.x) + pathHash(uint(pixel.y) + pathHash(uint(u_firstSample + k))));
        float jx = rng(), jy = rng();
        float ndcX = 2.0 * (float(pixel.x) + jx) / float(u_imageSize.x) - 1.0;
        float ndcY = 1.0 - 2.0 * (float(pixel.y) + jy) / float(u_imageSize.y);
        vec3 rd = projectionRay(ndcX, ndcY, aspect, u_cameraRight, u_cameraUp, u_cameraForward, u_tanHalfFovY,
                                u_halfFovY, u_projection);
        vec3 ro = u_cameraPosition;
        float a1 = rng(), a2 = rng();
        thinLensRay(ro, rd, u_cameraForward, u_cameraRight, u_cameraUp, a1, a2);
        float tStart, tEnd;
        bool hit = false;
        MarchState s = marchStart(0.0);
        if (clipCameraRay(ro, rd, tStart, tEnd)) {
            s = marchStart(tStart);
            marchRay(ro, rd, tEnd, pixelAngle, u_maxSteps, s, deEvals);
            hit = countsAsHit(s, pixelAngle);
        }
        if (!hit) {
            if (u_transparentBackground == 0)
                sumBeauty += envActive() && u_envVisible != 0 ? envRadiance(rd) : shadeBackground(rd);
            continue;
        }
        float eps = surfaceEpsilon(s.t, pixelAngle);
        vec3 pos = ro + rd * s.t;
        vec3 throughput = vec3(1.0), diffuseDirect = vec3(0.0), specular = vec3(0.0), emission = vec3(0.0),
             bsdfDirect = vec3(0.0), indirect = vec3(0.0), ratioDiffuse = vec3(0.0), ratioSpecular = vec3(0.0);
        for (int depth = 0;; ++depth) {
            vec3 n = surfaceNormal(pos, rd, eps, deEvals);
            vec3 albedo = surfaceAlbedo(pos, deEvals);
            if (depth == 0) {
                sumAlbedo += albedo;
                sumNormal += n;
                emission = albedo * u_emission;
            } else {
                indirect += throughput * albedo * u_emission;
            }
            vec3 wo = -rd;
            vec3 origin = pos + n * (2.0 * eps);
            for (int l = 0; l < u_lightCount; ++l) {
                float u1 = rng(), u2 = rng();
                vec3 wi, li;
                float dist;
                if (!sampleLight(l, origin, u1, u2, wi, li, dist)) continue;
                float cosI = dot(n, wi);
                if (cosI <= 0.0) continue;
                if (traceSecondary(origin, wi, eps, dist, deEvals) < INFINITY) continue;
                vec3 fd, fs;
                evalBsdf(albedo, n, wo, wi, fd, fs);
                if (depth == 0) {
                    diffuseDirect += fd * cosI * li;
                    specular += fs * cosI * li;
                } else {
                    indirect += throughput * (fd + fs) * cosI * li;
                }
            }
            if (envActive()) {
                float u1 = rng(), u2 = rng();
                float pdf;
                vec3 wi = envSample(u1, u2, pdf);
                float cosI = dot(n, wi);
                if (pdf > 0.0 && cosI > 0.0 && traceSecondary(origin, wi, eps, INFINITY, deEvals) == INFINITY) {
                    vec3 fd, fs;
                    evalBsdf(albedo, n, wo, wi, fd, fs);
                    float pb = bsdfPdf(n, wo, wi);
                    vec3 li = envRadiance(wi) * (pdf / (pdf * pdf + pb * pb));
                    if (depth == 0) {
                        diffuseDirect += fd * cosI * li;
                        specular += fs * cosI * li;
                    } else {
                        indirect += throughput * (fd + fs) * cosI * li;
                    }
                }
            }
            if (depth >= u_bounces) break;
            float uLobe = rng(), u1 = rng(), u2 = rng();
            vec3 wi = sampleBsdf(n, wo, uLobe, u1, u2);
            float cosI = dot(n, wi);
            float pdf = bsdfPdf(n, wo, wi);
            if (cosI <= 0.0 || pdf <= 0.0) break;
            vec3 fd, fs;
            evalBsdf(albedo, n, wo, wi, fd, fs);
            vec3 f = fd + fs;
            if (depth == 0) {
                ratioDiffuse = mix(vec3(0.0), fd / max(f, vec3(1e-30)), greaterThan(f, vec3(0.0)));
                ratioSpecular = mix(vec3(0.0), fs / max(f, vec3(1e-30)), greaterThan(f, vec3(0.0)));
            }
            throughput *= f * (cosI / pdf);
            float t = traceSecondary(origin, wi, eps, INFINITY, deEvals);
            if (t == INFINITY) {
                vec3 li = pathBackground(wi);
                if (envActive()) {
                    float pe = envPdf(wi);
                    li *= pdf * pdf / (pdf * pdf + pe * pe);
                }
                if (depth == 0) bsdfDirect += throughput * li; else indirect += throughput * li;
                break;
            }
            pos = origin + wi * t;
            rd = wi;
        }
        diffuseDirect += bsdfDirect * ratioDiffuse;
        specular += (bsdfDirect + indirect) * ratioSpecular;
        vec3 diffuseIndirect = indirect * ratioDiffuse;
        sumBeauty += emission + diffuseDirect + diffuseIndirect + specular;
        sumDiffuseDirect += diffuseDirect;
        sumDiffuseIndirect += diffuseIndirect;
        sumSpecular += specular;
        sumEmission += emission;
        coverage += 1.0;
    }
    // The in-focus depth, once (the first draw): the lens-centre ray through the pixel centre.
    float depth = 0.0;
    if (u_writeDepth != 0) {
        depth = 1e30;
        vec3 rd = projectionRay(2.0 * (float(pixel.x) + 0.5) / float(u_imageSize.x) - 1.0,
                                1.0 - 2.0 * (float(pixel.y) + 0.5) / float(u_imageSize.y), aspect, u_cameraRight,
                                u_cameraUp, u_cameraForward, u_tanHalfFovY, u_halfFovY, u_projection);
        float tStart, tEnd;
        if (clipCameraRay(u_cameraPosition, rd, tStart, tEnd)) {
            MarchState s = marchStart(tStart);
            marchRay(u_cameraPosition, rd, tEnd, pixelAngle, u_maxSteps, s, deEvals);
            if (s.status == MARCH_HIT) depth = s.t;
        }
    }
    outBeauty = vec4(sumBeauty, coverage);
    outDiffuseDirect = vec4(sumDiffuseDirect, deEvals);
    outDiffuseIndirect = vec4(sumDiffuseIndirect, 0.0);
    outSpecular = vec4(sumSpecular, 0.0);
    outEmission = vec4(sumEmission, 0.0);
    outAlbedo = vec4(sumAlbedo, 0.0);
    outNormalDepth = vec4(sumNormal, depth);
}
