#include "core/cpu_render/cpu_path_tracer.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <thread>

#include "core/cpu_render/cpu_shading.hpp"

namespace fraktal {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Rng {
    uint32_t state;
    double next() {
        state = pathHash(state);
        return double(state >> 8) * (1.0 / 16777216.0);
    }
};

// An orthonormal frame about unit `n` (Duff et al. 2017, "Building an orthonormal basis, revisited").
void frameAbout(const vec3& n, vec3& t, vec3& b) {
    const double sign = n.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sign + n.z);
    const double c = n.x * n.y * a;
    t = vec3(1.0 + sign * n.x * n.x * a, sign * c, -sign * n.x);
    b = vec3(c, sign + n.y * n.y * a, -n.y);
}

vec3 fromFrame(const vec3& n, double x, double y, double z) {
    vec3 t, b;
    frameAbout(n, t, b);
    return t * x + b * y + n * z;
}

// A direction in the cone of half-angle acos(cosMax) about `axis`, uniform in solid angle.
vec3 sampleCone(const vec3& axis, double cosMax, double u1, double u2) {
    const double cosTheta = 1.0 - u1 * (1.0 - cosMax);
    const double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
    const double phi = 2.0 * kPi * u2;
    return fromFrame(axis, sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta);
}

struct Bsdf {
    vec3 albedo;
    double alpha, f0, specularProbability;
};

double ggxD(double alpha, double cosH) {
    const double a2 = alpha * alpha;
    const double k = cosH * cosH * (a2 - 1.0) + 1.0;
    return a2 / (kPi * k * k);
}
double smithG1(double alpha, double cosV) {
    const double a2 = alpha * alpha;
    return 2.0 * cosV / (cosV + std::sqrt(a2 + (1.0 - a2) * cosV * cosV));
}

// The diffuse and specular parts of f(wo, wi), without the cosine.
void evalBsdf(const Bsdf& m, const vec3& n, const vec3& wo, const vec3& wi, vec3& fd, vec3& fs) {
    const double cosI = dot(n, wi), cosO = dot(n, wo);
    fd = m.albedo * ((1.0 - m.f0) / kPi);
    fs = vec3(0.0);
    if (cosI <= 0.0 || cosO <= 0.0 || m.f0 <= 0.0) return;
    const vec3 h = normalize(wi + wo);
    const double fresnel = m.f0 + (1.0 - m.f0) * std::pow(1.0 - std::clamp(dot(wo, h), 0.0, 1.0), 5.0);
    const double spec =
        fresnel * ggxD(m.alpha, dot(n, h)) * smithG1(m.alpha, cosI) * smithG1(m.alpha, cosO) / (4.0 * cosI * cosO);
    fs = vec3(spec);
}

double bsdfPdf(const Bsdf& m, const vec3& n, const vec3& wo, const vec3& wi) {
    const double cosI = dot(n, wi);
    if (cosI <= 0.0) return 0.0;
    double pdf = (1.0 - m.specularProbability) * cosI / kPi;
    if (m.specularProbability > 0.0) {
        const vec3 h = normalize(wi + wo);
        const double woh = dot(wo, h);
        if (woh > 0.0) pdf += m.specularProbability * ggxD(m.alpha, dot(n, h)) * dot(n, h) / (4.0 * woh);
    }
    return pdf;
}

vec3 sampleBsdf(const Bsdf& m, const vec3& n, const vec3& wo, double uLobe, double u1, double u2) {
    if (uLobe < m.specularProbability) {
        const double a2 = m.alpha * m.alpha;
        const double cosH = std::sqrt((1.0 - u1) / (1.0 + (a2 - 1.0) * u1));
        const double sinH = std::sqrt(std::max(0.0, 1.0 - cosH * cosH));
        const double phi = 2.0 * kPi * u2;
        const vec3 h = fromFrame(n, sinH * std::cos(phi), sinH * std::sin(phi), cosH);
        return glm::reflect(-wo, h);
    }
    const double r = std::sqrt(u1), phi = 2.0 * kPi * u2;
    return fromFrame(n, r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - u1)));
}

struct Tracer {
    const PathScene& scene;
    const cpu::Scene march;
    double pixelAngle;

    // Plain sphere tracing (pathtrace.frag's traceSecondary): the distance to the first point with
    // DE < eps, or kInfinity.
    double traceSecondary(const vec3& ro, const vec3& rd, double eps, double maxDistance, double& deEvals) const {
        double tStart, tEnd;
        if (!cpu::clipToBound(march, ro, rd, tStart, tEnd)) return kInfinity;
        cpu::MarchRule rule;
        rule.epsilon = eps;
        const auto at = [this](const vec3& p, double threshold) { return march.sample(p, threshold); };
        return cpu::traceFirstHit(at, ro, rd, tStart, std::min(tEnd, maxDistance), rule, scene.render.maxSteps, deEvals)
            .value_or(kInfinity);
    }

    vec3 background(const vec3& rd) const {
        return scene.environment.empty() ? cpu::shadeBackground(march, rd) : scene.environment.radiance(rd);
    }

    // One light sample seen from `p`: direction, radiance over pdf, and distance to the light.
    bool sampleLight(const Light& l, const vec3& p, double u1, double u2, vec3& wi, vec3& li, double& dist) const {
        const vec3 power = l.color * l.intensity;
        if (l.type == LightType::Directional) {
            const vec3 axis = normalize(l.direction);
            wi = l.size > 0.0 ? sampleCone(axis, std::cos(l.size * kPi / 180.0), u1, u2) : axis;
            li = power;
            dist = kInfinity;
            return true;
        }
        if (l.type == LightType::Sphere) {
            const vec3 toCentre = l.position - p;
            const double d = length(toCentre);
            if (d <= l.size || d <= 0.0) return false;
            if (l.size <= 0.0) {
                wi = toCentre / d;
                li = power / (d * d);
                dist = d;
                return true;
            }
            const double sinMax2 = l.size * l.size / (d * d);
            const double cosMax = std::sqrt(std::max(0.0, 1.0 - sinMax2));
            wi = sampleCone(toCentre / d, cosMax, u1, u2);
            const double b = dot(toCentre, wi);
            dist = b - std::sqrt(std::max(0.0, b * b - (d * d - l.size * l.size)));
            li = power / (kPi * l.size * l.size) * (2.0 * kPi * (1.0 - cosMax));
            return true;
        }
        const vec3 n = normalize(l.normal);
        const vec3 up = normalize(l.up - n * dot(n, l.up));
        const vec3 right = glm::cross(up, n);
        const vec3 q = l.position + right * ((u1 - 0.5) * l.size) + up * ((u2 - 0.5) * l.height);
        const vec3 toQ = q - p;
        dist = length(toQ);
        if (dist <= 0.0) return false;
        wi = toQ / dist;
        const double cosLight = -dot(n, wi);
        if (cosLight <= 0.0) return false;
        li = power * (l.size * l.height * cosLight / (dist * dist));
        return true;
    }

    void samplePixel(int x, int y, int sample, PathImage& out, double& deEvals) const {
        const RenderSettings& render = scene.render;
        const Lighting& lighting = scene.lighting;
        const EnvironmentMap& env = scene.environment;
        Rng rng{pathSeed(x, y, sample)};
        const double jx = rng.next(), jy = rng.next();
        const double aspect = double(render.width) / double(render.height);
        const double ndcX = 2.0 * (x + jx) / render.width - 1.0;
        const double ndcY = 1.0 - 2.0 * (y + jy) / render.height;
        const Camera& camera = scene.camera;
        vec3 rd = camera.rayDirection(ndcX, ndcY, aspect);
        vec3 ro = camera.position;
        const double a1 = rng.next(), a2 = rng.next();
        // The wide projections are pinholes (setLensUniforms).
        if (lighting.lens.enabled() && camera.projection == Projection::Perspective) {
            const CameraBasis basis = camera.basis();
            const double focus = focusDistanceOf(lighting.lens, camera);
            const vec3 focusPoint = ro + rd * (focus / dot(rd, basis.forward));
            const vec2 lens = sampleAperture(a1, a2, lighting.lens.blades) * lighting.lens.apertureRadius;
            ro = ro + basis.right * lens.x + basis.up * lens.y;
            rd = normalize(focusPoint - ro);
        }

        double tStart, tEnd;
        bool hit = false;
        cpu::MarchState s = cpu::marchStart(march, 0.0);
        if (cpu::clipCameraRay(march, ro, rd, tStart, tEnd)) {
            s = cpu::marchStart(march, tStart);
            cpu::marchRay(march, ro, rd, tEnd, pixelAngle, render.maxSteps, s, deEvals);
            hit = cpu::countsAsHit(march, s, pixelAngle);
        }
        float* beauty = out.at(kBeauty, x, y);
        if (!hit) {
            if (!render.transparentBackground) {
                const vec3 bg =
                    env.empty() || lighting.environment.visible ? background(rd) : cpu::shadeBackground(march, rd);
                for (int c = 0; c < 3; ++c) beauty[c] += float(bg[c]);
            }
            return;
        }
        const double eps = cpu::surfaceEpsilon(march, s.t, pixelAngle);
        vec3 pos = ro + rd * s.t;
        vec3 throughput(1.0), diffuseDirect(0.0), specular(0.0), emission(0.0), bsdfDirect(0.0), indirect(0.0),
            ratioDiffuse(0.0), ratioSpecular(0.0);
        const PathTraceSettings& pt = lighting.pathTrace;
        for (int depth = 0;; ++depth) {
            const vec3 n = cpu::surfaceNormal(march, pos, rd, eps, deEvals);
            const Bsdf m{cpu::surfaceAlbedo(march, pos, deEvals), pt.roughness * pt.roughness, pt.specular,
                         pt.specular > 0.0 ? 0.5 : 0.0};
            if (depth == 0) {
                for (int c = 0; c < 3; ++c) {
                    out.at(kAlbedo, x, y)[c] += float(m.albedo[c]);
                    out.at(kNormal, x, y)[c] += float(n[c]);
                }
                emission = m.albedo * pt.emission;
            } else {
                indirect += throughput * m.albedo * pt.emission;
            }
            const vec3 wo = -rd;
            const vec3 origin = pos + n * (2.0 * eps);
            // Next-event estimation: every light, then the environment.
            for (const Light& l : lighting.lights) {
                const double u1 = rng.next(), u2 = rng.next();
                vec3 wi, li;
                double dist;
                if (!l.enabled || !sampleLight(l, origin, u1, u2, wi, li, dist)) continue;
                const double cosI = dot(n, wi);
                if (cosI <= 0.0) continue;
                if (traceSecondary(origin, wi, eps, dist, deEvals) < kInfinity) continue;
                vec3 fd, fs;
                evalBsdf(m, n, wo, wi, fd, fs);
                if (depth == 0) {
                    diffuseDirect += fd * cosI * li;
                    specular += fs * cosI * li;
                } else {
                    indirect += throughput * (fd + fs) * cosI * li;
                }
            }
            if (!env.empty()) {
                const double u1 = rng.next(), u2 = rng.next();
                double pdf;
                const vec3 wi = env.sample(u1, u2, pdf);
                const double cosI = dot(n, wi);
                if (pdf > 0.0 && cosI > 0.0 && traceSecondary(origin, wi, eps, kInfinity, deEvals) == kInfinity) {
                    vec3 fd, fs;
                    evalBsdf(m, n, wo, wi, fd, fs);
                    const double pb = bsdfPdf(m, n, wo, wi);
                    const vec3 li = env.radiance(wi) * (pdf / (pdf * pdf + pb * pb));
                    if (depth == 0) {
                        diffuseDirect += fd * cosI * li;
                        specular += fs * cosI * li;
                    } else {
                        indirect += throughput * (fd + fs) * cosI * li;
                    }
                }
            }
            if (depth >= pt.bounces) break;
            const double uLobe = rng.next(), u1 = rng.next(), u2 = rng.next();
            const vec3 wi = sampleBsdf(m, n, wo, uLobe, u1, u2);
            const double cosI = dot(n, wi);
            const double pdf = bsdfPdf(m, n, wo, wi);
            if (cosI <= 0.0 || pdf <= 0.0) break;
            vec3 fd, fs;
            evalBsdf(m, n, wo, wi, fd, fs);
            const vec3 f = fd + fs;
            if (depth == 0)
                for (int c = 0; c < 3; ++c) {
                    ratioDiffuse[c] = f[c] > 0.0 ? fd[c] / f[c] : 0.0;
                    ratioSpecular[c] = f[c] > 0.0 ? fs[c] / f[c] : 0.0;
                }
            throughput *= f * (cosI / pdf);
            const double t = traceSecondary(origin, wi, eps, kInfinity, deEvals);
            if (t == kInfinity) {
                vec3 li = background(wi);
                if (!env.empty()) {
                    const double pe = env.pdf(wi);
                    li *= pdf * pdf / (pdf * pdf + pe * pe);
                }
                (depth == 0 ? bsdfDirect : indirect) += throughput * li;
                break;
            }
            pos = origin + wi * t;
            rd = wi;
        }
        diffuseDirect += bsdfDirect * ratioDiffuse;
        specular += (bsdfDirect + indirect) * ratioSpecular;
        const vec3 diffuseIndirect = indirect * ratioDiffuse;
        const vec3 total = emission + diffuseDirect + diffuseIndirect + specular;
        for (int c = 0; c < 3; ++c) {
            beauty[c] += float(total[c]);
            out.at(kDiffuseDirect, x, y)[c] += float(diffuseDirect[c]);
            out.at(kDiffuseIndirect, x, y)[c] += float(diffuseIndirect[c]);
            out.at(kSpecular, x, y)[c] += float(specular[c]);
            out.at(kEmission, x, y)[c] += float(emission[c]);
        }
        beauty[3] += 1.0f;
    }

    // The in-focus depth: the lens-centre ray through the pixel centre.
    float focusDepth(int x, int y, double& deEvals) const {
        const double aspect = double(scene.render.width) / double(scene.render.height);
        const vec3 rd = scene.camera.rayDirection(2.0 * (x + 0.5) / scene.render.width - 1.0,
                                                  1.0 - 2.0 * (y + 0.5) / scene.render.height, aspect);
        double tStart, tEnd;
        if (!cpu::clipCameraRay(march, scene.camera.position, rd, tStart, tEnd)) return 1e30f;
        cpu::MarchState s = cpu::marchStart(march, tStart);
        cpu::marchRay(march, scene.camera.position, rd, tEnd, pixelAngle, scene.render.maxSteps, s, deEvals);
        return s.status == cpu::MarchStatus::Hit ? float(s.t) : 1e30f;
    }
};

}  // namespace

uint32_t pathHash(uint32_t v) {  // PCG-RXS-M-XS (Jarzynski and Olano 2020)
    const uint32_t state = v * 747796405u + 2891336453u;
    const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
    return (word >> 22u) ^ word;
}

uint32_t pathSeed(int x, int y, int sample) {
    return pathHash(uint32_t(x) + pathHash(uint32_t(y) + pathHash(uint32_t(sample))));
}

vec2 sampleAperture(double u1, double u2, int blades) {
    if (blades < 3) {  // Shirley-Chiu concentric map of the square onto the disc
        const double a = 2.0 * u1 - 1.0, b = 2.0 * u2 - 1.0;
        if (a == 0.0 && b == 0.0) return vec2(0.0);
        double r, phi;
        if (std::abs(a) > std::abs(b)) {
            r = a;
            phi = (kPi / 4.0) * (b / a);
        } else {
            r = b;
            phi = kPi / 2.0 - (kPi / 4.0) * (a / b);
        }
        return vec2(r * std::cos(phi), r * std::sin(phi));
    }
    // A triangle of the polygon (centre, corner k, corner k + 1), then a uniform point in it.
    const double scaled = u1 * blades;
    const int k = std::min(int(scaled), blades - 1);
    const double v1 = scaled - k;
    const double a0 = kPi / 2.0 + 2.0 * kPi * k / blades, a1 = a0 + 2.0 * kPi / blades;
    const double su = std::sqrt(v1);
    const double wa = su * (1.0 - u2), wb = su * u2;
    return vec2(wa * std::cos(a0) + wb * std::cos(a1), wa * std::sin(a0) + wb * std::sin(a1));
}

std::vector<Light> resolveLights(const std::vector<Light>& lights, const std::function<vec3(const vec3&)>& toWorking) {
    std::vector<Light> out = lights;
    if (toWorking)
        for (Light& l : out) l.color = toWorking(l.color);
    return out;
}

PathImage pathTraceReference(const PathScene& scene, int firstSample, int samples, int threads) {
    PathImage image;
    const int w = scene.render.width, h = scene.render.height;
    image.resize(w, h);
    image.spp = samples;
    const Tracer tracer{scene, cpu::Scene{scene.formula, scene.shading}, scene.camera.pixelAngle(h, w)};
    std::atomic<int> nextRow{0};
    auto worker = [&] {
        for (int y = nextRow++; y < h; y = nextRow++)
            for (int x = 0; x < w; ++x) {
                double deEvals = 0.0;
                for (int k = 0; k < samples; ++k) tracer.samplePixel(x, y, firstSample + k, image, deEvals);
                const float inv = 1.0f / float(std::max(samples, 1));
                for (auto& pass : image.passes)
                    for (int c = 0; c < 4; ++c) (&pass[(size_t(y) * w + x) * 4])[c] *= inv;
                image.at(kNormal, x, y)[3] = tracer.focusDepth(x, y, deEvals);
            }
    };
    const int n = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return image;
}

}  // namespace fraktal
