#include "core/cpu_render/cpu_shading.hpp"

#include <algorithm>
#include <cmath>

namespace fraktal::cpu {

double Scene::de(const vec3& p, double& deEvals, double hitThreshold) const {
    deEvals += 1.0;
    return evaluate(formula, p, hitThreshold).distance;
}

DistanceSample Scene::sample(const vec3& p, double hitThreshold) const {
    const Evaluation e = evaluate(formula, p, hitThreshold);
    return {e.distance, e.inside};
}

// Mirror of march.glsl's refineHit (why: there).
constexpr int kRefineSteps = 3;
constexpr double kRefineLevel = 0.5;

void refineHit(const Scene& scene, const vec3& ro, const vec3& rd, double pixelAngle, double d, MarchState& s,
               double& deEvals) {
    if (scene.formula.hitRule != HitRule::Surface) return;
    for (int i = 0; i < kRefineSteps; ++i) {
        if (i > 0) {
            d = scene.de(ro + rd * s.t, deEvals);
            s.steps += 1;
        }
        s.t += d - kRefineLevel * pixelAngle * s.t * scene.params.detail;
    }
}

MarchState marchStart(const Scene& scene, double tStart) {
    MarchState s;
    s.t = tStart;
    s.omega = quantizedOmega(std::max(scene.params.overRelaxation, 1.0));
    return s;
}

MarchRule cameraRule(const Scene& scene, double pixelAngle) {
    MarchRule rule;
    rule.coneAngle = pixelAngle * scene.params.detail;
    rule.hitRule = scene.formula.hitRule;
    rule.recoverOvershoot = true;
    rule.maxStepGrowth = scene.params.maxStepGrowth;
    return rule;
}

void marchRay(const Scene& scene, const vec3& ro, const vec3& rd, double tEnd, double pixelAngle, int maxSteps,
              MarchState& s, double& deEvals) {
    const auto at = [&scene](const vec3& p, double threshold) { return scene.sample(p, threshold); };
    marchSteps(at, ro, rd, tEnd, cameraRule(scene, pixelAngle), maxSteps, s, deEvals);
    if (s.status == MarchStatus::Hit) refineHit(scene, ro, rd, pixelAngle, s.lastD, s, deEvals);
}

bool countsAsHit(const Scene& scene, const MarchState& s, double pixelAngle) {
    if (scene.formula.hitRule == HitRule::InteriorWalls) return s.status == MarchStatus::Hit;
    return s.status == MarchStatus::Hit ||
           (s.status == MarchStatus::Marching && s.lastD < 10.0 * pixelAngle * s.t * scene.params.detail);
}

bool clipToBound(const Scene& scene, const vec3& ro, const vec3& rd, double& tStart, double& tEnd) {
    const double r = scene.formula.boundRadius;
    const double b = dot(ro, rd);
    const double c = dot(ro, ro) - r * r;
    double h = b * b - c;
    tStart = 0.0;
    tEnd = -1.0;
    if (h < 0.0) return false;
    h = std::sqrt(h);
    tStart = std::max(-b - h, 0.0);
    tEnd = -b + h;
    return tEnd > 0.0;
}

bool clipCameraRay(const Scene& scene, const vec3& ro, const vec3& rd, double& tStart, double& tEnd) {
    if (!clipToBound(scene, ro, rd, tStart, tEnd)) return false;
    if (scene.params.viewDistance > 0.0) tEnd = std::min(tEnd, scene.params.viewDistance);
    return tEnd > tStart;
}

double surfaceEpsilon(const Scene& scene, double t, double pixelAngle) {
    return std::max(0.5 * pixelAngle * t, 2e-5 * scene.formula.boundRadius);
}

// Mirror of shade.glsl's surfaceNormal (tetrahedral differences, why: there).
vec3 surfaceNormal(const Scene& scene, const vec3& pos, const vec3& rd, double eps, double& deEvals) {
    const vec3 corners[4] = {vec3(1, -1, -1), vec3(-1, -1, 1), vec3(-1, 1, -1), vec3(1, 1, 1)};
    vec3 n(0.0);
    for (const vec3& k : corners) n += k * scene.de(pos + k * eps, deEvals);
    const double len = length(n);
    return len > 1e-20 ? n / len : -rd;
}

vec3 surfaceAlbedo(const Scene& scene, const vec3& pos, double& deEvals) {
    deEvals += 1.0;
    return albedoOf(scene.params, evaluate(scene.formula, pos));
}

namespace {

double ambientOcclusion(const Scene& scene, const vec3& pos, const vec3& n, double& deEvals) {
    const ShadingSettings& s = scene.params.s;
    if (s.aoSteps <= 0) return 1.0;
    double occlusion = 0.0;
    for (int i = 1; i <= s.aoSteps; ++i) {
        const double h = s.aoDistance * double(i) / double(s.aoSteps);
        // A fractal carved by an escape-time one reads its carved space as 1.5 h: open, not occluded.
        const double d = scene.de(pos + n * h, deEvals, h);
        occlusion += std::clamp((h - d) / h, 0.0, 1.0);
    }
    return std::clamp(1.0 - s.aoStrength * occlusion / double(s.aoSteps), 0.0, 1.0);
}

double softShadow(const Scene& scene, const vec3& ro, const vec3& L, double eps, double& deEvals) {
    const ShadingSettings& s = scene.params.s;
    if (s.shadowSteps <= 0) return 1.0;
    double tStart, tEnd;
    if (!clipToBound(scene, ro, L, tStart, tEnd)) return 1.0;
    double result = 1.0;
    double t = std::max(tStart, 2.0 * eps);
    for (int i = 0; i < s.shadowSteps && t < tEnd; ++i) {
        // A carved space reads as 1.5 t / softness: lit, as in ambientOcclusion.
        const double d = scene.de(ro + L * t, deEvals, t / s.shadowSoftness);
        result = std::min(result, s.shadowSoftness * d / t);
        if (result < 1e-3) return 0.0;
        t += std::clamp(d, eps, 0.1 * scene.formula.boundRadius);
    }
    result = std::clamp(result, 0.0, 1.0);
    return result * result * (3.0 - 2.0 * result);
}

vec3 lightSurface(const Scene& scene, const vec3& n, const vec3& rd, const vec3& albedo, double ao, double shadow) {
    const ShadingSettings& s = scene.params.s;
    const vec3 L = s.lightDirection;
    const double diffuse = std::max(dot(n, L), 0.0);
    const vec3 h = normalize(L - rd);
    const double specular = diffuse > 0.0 ? s.specular * std::pow(std::max(dot(n, h), 0.0), s.shininess) : 0.0;
    const double sky = 0.5 + 0.5 * n.y;
    return albedo * (s.lightColor * (diffuse * shadow) + s.fillColor * (sky * ao)) + s.lightColor * (specular * shadow);
}

vec3 applyFog(const Scene& scene, const vec3& color, double t) {
    return glm::mix(scene.params.s.fogColor, color, std::exp(-scene.params.s.fogDensity * t));
}

vec3 reflectedColor(const Scene& scene, const vec3& pos, const vec3& n, const vec3& rd, double t, double pixelAngle,
                    double eps, double& deEvals) {
    const vec3 rr = glm::reflect(rd, n);
    const vec3 ro = pos + n * (2.0 * eps);
    double tStart, tEnd;
    if (!clipToBound(scene, ro, rr, tStart, tEnd)) return shadeBackground(scene, rr);
    MarchState s = marchStart(scene, tStart);
    marchRay(scene, ro, rr, tEnd, pixelAngle, scene.params.s.reflectionSteps, s, deEvals);
    if (s.status != MarchStatus::Hit) return shadeBackground(scene, rr);
    const vec3 p2 = ro + rr * s.t;
    const double eps2 = surfaceEpsilon(scene, t + s.t, pixelAngle);
    const vec3 n2 = surfaceNormal(scene, p2, rr, eps2, deEvals);
    const vec3 albedo2 = surfaceAlbedo(scene, p2, deEvals);
    return applyFog(scene, lightSurface(scene, n2, rr, albedo2, 1.0, 1.0), s.t);
}

}  // namespace

vec3 shadeBackground(const Scene& scene, const vec3& rd) {
    return glm::mix(scene.params.s.backgroundBottom, scene.params.s.backgroundTop, 0.5 + 0.5 * rd.y);
}

SurfaceSample shadeSurface(const Scene& scene, const vec3& pos, const vec3& rd, double t, double pixelAngle,
                           double& deEvals) {
    const ShadingSettings& s = scene.params.s;
    SurfaceSample result;
    const double eps = surfaceEpsilon(scene, t, pixelAngle);
    const vec3 n = surfaceNormal(scene, pos, rd, eps, deEvals);
    const vec3 albedo = surfaceAlbedo(scene, pos, deEvals);
    const double ao = ambientOcclusion(scene, pos, n, deEvals);
    // As in shaders/shade.glsl: facing away from the key light, nothing the shadow scales is lit.
    const double shadow =
        dot(n, s.lightDirection) > 0.0 ? softShadow(scene, pos + n * (2.0 * eps), s.lightDirection, eps, deEvals) : 1.0;
    vec3 color = lightSurface(scene, n, rd, albedo, ao, shadow);
    if (s.reflection > 0.0) {
        const double cosine = std::clamp(-dot(rd, n), 0.0, 1.0);
        const double fresnel = s.reflection + (1.0 - s.reflection) * std::pow(1.0 - cosine, 5.0);
        color = glm::mix(color, reflectedColor(scene, pos, n, rd, t, pixelAngle, eps, deEvals), fresnel);
    }
    result.color = applyFog(scene, color, t);
    result.normal = n;
    result.albedo = albedo;
    result.ao = ao;
    return result;
}

}  // namespace fraktal::cpu
