#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbox box fold (seed 2.2.3): boxFold(v) = clamp(v, -L, L) * 2 - v.
struct BoxFold {
    static constexpr std::string_view id = "box_fold";
    static constexpr std::string_view label = "Box fold";
    static constexpr std::string_view help =
        "Mandelbox box fold: reflect each coordinate that leaves [-L, L] back inside.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 8.0, "Folding limit L."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz = clamp(p.xyz, -limit, limit) * 2.0 - p.xyz;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double limit = a.f(0);
        p.xyz = clamp(p.xyz, -limit, limit) * 2.0 - p.xyz;
    }
};

}  // namespace fraktal::blocks
