#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Smooth Mandelbox box fold: |x + L| - |x - L| - x with |t| replaced by sqrt(t^2 + k^2), so
// the folded object has no creases. Each coordinate's derivative is
// s'(x + L) - s'(x - L) - 1 with 0 <= s'(x + L) - s'(x - L) <= 2, i.e. within [-1, 1]: the
// fold does not stretch space and the running derivative is unchanged (a bound of 1).
struct SmoothBoxFold {
    static constexpr std::string_view id = "smooth_box_fold";
    static constexpr std::string_view label = "Smooth box fold";
    static constexpr std::string_view help = "Mandelbox box fold with rounded corners: |t| becomes sqrt(t^2 + k^2).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 4.0, "Folding limit L."},
        ParamDecl{"smoothness", ParamType::Float, {0.1, 0.0, 0.0}, 0.001, 1.0, "Rounding k of the fold's corners."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 a = p.xyz + limit, b = p.xyz - limit;
    float k2 = smoothness * smoothness;
    p.xyz = sqrt(a * a + k2) - sqrt(b * b + k2) - p.xyz;
)";
    static void apply(P4& p, const vec3&, Args args) {
        const double limit = args.f(0), smoothness = args.f(1);
        vec3 a = p.xyz + limit, b = p.xyz - limit;
        double k2 = smoothness * smoothness;
        p.xyz = glm::sqrt(a * a + k2) - glm::sqrt(b * b + k2) - p.xyz;
    }
};

}  // namespace fraktal::blocks
