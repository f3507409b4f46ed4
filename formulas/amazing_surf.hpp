#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Amazing Surf (Kali; Mandelbulber2 amazing_surf): a box fold of x and y only, then a sphere
// fold with a minimum radius and a scale, m = s / clamp(|v|^2, Rm^2, 1). Folds keep distances
// and the sphere fold is conformal, so the running derivative is multiplied by |m|. Follow it
// with add_c for the Mandelbrot form.
struct AmazingSurf {
    static constexpr std::string_view id = "amazing_surf";
    static constexpr std::string_view label = "Amazing Surf";
    static constexpr std::string_view help =
        "Box fold of x and y, then sphere fold with scale (Kali's Amazing Surf); add c after it.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"fold", ParamType::Vec3, {1.0, 1.0, 0.0}, 0.0, 4.0, "Folding limits of x and y (z is unused)."},
        ParamDecl{"min_radius", ParamType::Float, {0.5, 0.0, 0.0}, 0.05, 1.0, "Inner radius Rm of the sphere fold."},
        ParamDecl{"scale", ParamType::Float, {2.0, 0.0, 0.0}, -4.0, 4.0, "Scale s of the sphere fold."},
    };

    static constexpr std::string_view glsl = R"(
    p.xy = abs(p.xy + fold.xy) - abs(p.xy - fold.xy) - p.xy;
    float m = scale / clamp(dot(p.xyz, p.xyz), min_radius * min_radius, 1.0);
    p.xyz *= m;
    p.w *= abs(m);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 fold = a.v3(0);
        const double min_radius = a.f(1), scale = a.f(2);
        p.xyz.x = abs(p.xyz.x + fold.x) - abs(p.xyz.x - fold.x) - p.xyz.x;
        p.xyz.y = abs(p.xyz.y + fold.y) - abs(p.xyz.y - fold.y) - p.xyz.y;
        double m = scale / clamp(dot(p.xyz, p.xyz), min_radius * min_radius, 1.0);
        p.xyz *= m;
        p.w *= abs(m);
    }
};

}  // namespace fraktal::blocks
