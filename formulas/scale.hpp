#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Uniform scale about a centre. Distances in the scaled space grow by |s|, so the running scale
// p.w does too (seed 3.2; PySpace FoldScaleTranslate).
struct Scale {
    static constexpr std::string_view id = "scale";
    static constexpr std::string_view label = "Scale";
    static constexpr std::string_view help =
        "Scale about a centre: p = (p - centre) * s + centre (and the fourth coordinate w times s); the running scale "
        "grows by |s|.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {2.0, 0.0, 0.0}, -4.0, 4.0, "Scale factor s."},
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, 0.0}, -10.0, 10.0, "Fixed point of the scaling."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz = (p.xyz - center) * scale + center;
    pointW *= scale;
    p.w *= abs(scale);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0);
        const vec3 center = a.v3(1);
        p.xyz = (p.xyz - center) * scale + center;
        p.pointW *= scale;
        p.w *= abs(scale);
    }
};

}  // namespace fraktal::blocks
