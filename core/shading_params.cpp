#include "core/shading_params.hpp"

#include <algorithm>

namespace fraktal {

ShadingParams resolveShading(const ShadingSettings& shading, const RenderSettings& render, const Formula& formula,
                             const std::function<vec3(const vec3&)>& toWorking) {
    ShadingParams p;
    p.s = shading;
    p.s.lightDirection = normalize(shading.lightDirection);
    p.s.aoDistance = shading.aoDistance * formula.boundRadius;
    p.s.fogDensity = shading.fogDensity / formula.boundRadius;
    if (toWorking) {
        for (vec3* c : {&p.s.lightColor, &p.s.fillColor, &p.s.fogColor, &p.s.backgroundTop, &p.s.backgroundBottom})
            *c = toWorking(*c);
    }
    for (size_t k = 0; k < formula.objects.size() && k < p.objectColors.size(); ++k)
        p.objectColors[k] = toWorking ? toWorking(formula.objects[k].color) : formula.objects[k].color;
    p.detail = render.detail;
    p.overRelaxation = render.overRelaxation;
    // Over-relaxation's first steps are already that long.
    p.maxStepGrowth = std::max(render.maxStepGrowth, render.overRelaxation);
    p.viewDistance = render.viewDistance;
    return p;
}

vec3 albedoOf(const ShadingParams& params, const Evaluation& e) {
    if (e.surface != kFractalSurface) return params.objectColors[size_t(e.surface)];
    const ShadingSettings& s = params.s;
    const double x = s.trapOffset + s.trapScale * dot(s.trapWeights, e.trap.value);
    const vec3 display =
        clamp(s.paletteA + s.paletteB * glm::cos(6.28318530718 * (s.paletteC * x + s.paletteD)), 0.0, 1.0);
    return glm::pow(display, vec3(2.2));
}

}  // namespace fraktal
