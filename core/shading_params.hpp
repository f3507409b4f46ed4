// ShadingSettings resolved for one formula: lengths in world units, the light direction
// normalised, colours in the working space. The GL uniforms (shading_uniforms.hpp) and the CPU
// reference renderer both take this, so they shade from identical numbers.
#pragma once

#include <array>
#include <functional>

#include "core/formula.hpp"
#include "core/render_settings.hpp"

namespace fraktal {

struct ShadingParams {
    ShadingSettings s;  // with aoDistance and fogDensity in world units, colours converted
    // Each object's colour (SceneObject::color) in the working space, by index in the formula's
    // objects (shade.glsl's u_objectColors; the rest unused).
    std::array<vec3, kMaxObjects> objectColors{};
    double detail = 0.5;
    double overRelaxation = 1.3;
    double maxStepGrowth = 1.9;
    double viewDistance = 0.0;  // camera rays end this far from the camera (0: no limit)

    bool operator==(const ShadingParams&) const = default;
};

// `toWorking` converts a linear Rec.709 colour into the working space (identity by default).
ShadingParams resolveShading(const ShadingSettings& shading, const RenderSettings& render, const Formula& formula,
                             const std::function<vec3(const vec3&)>& toWorking = {});

// The surface's albedo at an evaluated point, in the working space: the object's own colour, or
// the fractal's palette (cosine palette, Quilez) at its orbit trap, decoded from display to linear
// as shade.glsl's surfaceAlbedo does.
vec3 albedoOf(const ShadingParams& params, const Evaluation& e);

}  // namespace fraktal
