#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// A scale per axis: p = p * s componentwise. A negative factor mirrors its axis (Mandelbulber2's
// mandelbulb_power2 is the latitude bulb of power 2 with z mirrored); unequal factors stretch
// (box_fold_bulb_pow2's z factor). The map's largest stretch is max |s_i|, so the running scale
// grows by that: a Lipschitz bound, exact for a uniform scale or a mirror.
struct AxisScale {
    static constexpr std::string_view id = "axis_scale";
    static constexpr std::string_view label = "Scale per axis";
    static constexpr std::string_view help =
        "p = p * s per axis (a negative factor mirrors the axis); the running scale grows by the largest |s|.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Vec3, {1.0, 1.0, -1.0}, -100.0, 100.0, "Factor for x, y and z."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz *= scale;
    p.w *= max(abs(scale.x), max(abs(scale.y), abs(scale.z)));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 scale = a.v3(0);
        p.xyz *= scale;
        p.w *= max(abs(scale.x), max(abs(scale.y), abs(scale.z)));
    }
};

}  // namespace fraktal::blocks
