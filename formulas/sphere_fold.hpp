#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbox sphere fold (seed 2.2.3): v * Rf^2 / clamp(|v|^2, Rm^2, Rf^2). The running
// derivative is scaled by the same factor (Lowe's Mandelbox DE).
struct SphereFold {
    static constexpr std::string_view id = "sphere_fold";
    static constexpr std::string_view label = "Sphere fold";
    static constexpr std::string_view help =
        "Mandelbox sphere fold: invert in the sphere of radius Rf, linear inside Rm.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"min_radius",
                  ParamType::Float,
                  {0.5, 0.0, 0.0},
                  0.001,
                  4.0,
                  "Inner radius Rm: inside it the fold is a uniform scale."},
        ParamDecl{
            "fixed_radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.001, 4.0, "Fixed radius Rf: the sphere of inversion."},
    };

    static constexpr std::string_view glsl = R"(
    float rm2 = min_radius * min_radius;
    float rf2 = fixed_radius * fixed_radius;
    float k = rf2 / clamp(dot(p.xyz, p.xyz), min(rm2, rf2), rf2);
    p *= k;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double min_radius = a.f(0), fixed_radius = a.f(1);
        double rm2 = min_radius * min_radius;
        double rf2 = fixed_radius * fixed_radius;
        double k = rf2 / clamp(dot(p.xyz, p.xyz), min(rm2, rf2), rf2);
        p.xyz *= k, p.w *= k;
    }
};

}  // namespace fraktal::blocks
