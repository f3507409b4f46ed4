#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Inversion in the sphere of radius R about a centre: v -> R^2 (v - centre) / |v - centre|^2
// + centre. Inversion is conformal with local scale R^2 / |v - centre|^2, so the running
// derivative is multiplied by that factor (as the Mandelbox sphere fold does; Lowe).
struct SphereInvert {
    static constexpr std::string_view id = "sphere_invert";
    static constexpr std::string_view label = "Sphere inversion";
    static constexpr std::string_view help =
        "Invert in a sphere of radius R about a point (the centre); conformal, derivative scaled alike.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.05, 4.0, "Radius R of the sphere of inversion."},
        ParamDecl{
            "center", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Centre of inversion (the point inverted about)."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 d = p.xyz - center;
    float k = radius * radius / max(dot(d, d), 1e-12);
    p.xyz = d * k + center;
    p.w *= k;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double radius = a.f(0);
        const vec3 center = a.v3(1);
        vec3 d = p.xyz - center;
        double k = radius * radius / std::max(dot(d, d), 1e-12);
        p.xyz = d * k + center;
        p.w *= k;
    }
};

}  // namespace fraktal::blocks
