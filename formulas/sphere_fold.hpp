#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbox sphere fold (seed 2.2.3): v * Rf^2 / clamp(|v|^2, Rm^2, Rf^2). The running
// derivative is scaled by the same factor (Lowe's Mandelbox DE).
//
// With an offset o (Mandelbulber2's mandelbox_offset, fractal_formulas.cpp MandelboxIteration)
// the radii are still measured from the origin but the scaling is about -o: v' = (v + o) k - o.
// In the shell between the radii, k = Rf^2 / r^2 varies, and the Jacobian is
// k (I - 2 a b^T) with b = v / r and a = (v + o) / r; at o = 0 that is k times a reflection, so k
// bounds it, but off the origin it stretches by more. p.w carries k times the largest singular
// value of I - 2 a b^T, the root of l^2 - T l + D with T = 2 - 4 a.b + 4 |a|^2 and
// D = (1 - 2 a.b)^2 (|b| = 1). Mandelbulber2 carries k alone.
//
// The inner radius may grow with the iteration i: Rm^2 + growth i + curve i^2, as Mandelbulber2's
// Cpara curve moves the squared inner radius of abox_mod11's and pseudo_kleinian_mod2's folds
// (fractal_formulas.cpp AboxMod11Iteration; its piecewise curve is imported as one quadratic per
// window). k is still the fold's scale at the point, so the derivative bound holds at every
// iteration; Rm^2 never falls below the 1e-6 of the least inner radius.
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
        ParamDecl{"offset",
                  ParamType::Vec3,
                  {0.0, 0.0, 0.0},
                  -4.0,
                  4.0,
                  "Added before the scaling and taken away after it: the fold scales about -offset while its radii "
                  "stay measured from the origin (Mandelbulber2's offset)."},
        ParamDecl{"min_r2_growth",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -1.0,
                  1.0,
                  "Added to Rm^2 per iteration: at iteration i (from 0) the inner radius squared is Rm^2 + growth i + "
                  "curve i^2 (Mandelbulber2's Cpara curve)."},
        ParamDecl{"min_r2_curve",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -0.1,
                  0.1,
                  "Added to Rm^2 times the iteration squared: the growth's own change."},
    };

    static constexpr std::string_view glsl = R"(
    float rm2 = max(min_radius * min_radius + (min_r2_growth + min_r2_curve * float(iteration)) * float(iteration), 1e-6);
    float rf2 = fixed_radius * fixed_radius;
    float r2 = dot(p.xyz, p.xyz);
    float k = rf2 / clamp(r2, min(rm2, rf2), rf2);
    float stretch = k;
    if (offset != vec3(0.0) && r2 > min(rm2, rf2) && r2 < rf2) {
        float ab = 1.0 + dot(offset, p.xyz) / r2, aa = dot(p.xyz + offset, p.xyz + offset) / r2;
        float t = 2.0 - 4.0 * ab + 4.0 * aa, d = (1.0 - 2.0 * ab) * (1.0 - 2.0 * ab);
        stretch = k * sqrt(0.5 * (t + sqrt(max(t * t - 4.0 * d, 0.0))));
    }
    p.xyz = (p.xyz + offset) * k - offset;
    p.w *= stretch;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double min_radius = a.f(0), fixed_radius = a.f(1);
        const vec3 offset = a.v3(2);
        const double min_r2_growth = a.f(3), min_r2_curve = a.f(4);
        double rm2 = max(
            min_radius * min_radius + (min_r2_growth + min_r2_curve * double(p.iteration)) * double(p.iteration), 1e-6);
        double rf2 = fixed_radius * fixed_radius;
        double r2 = dot(p.xyz, p.xyz);
        double k = rf2 / clamp(r2, min(rm2, rf2), rf2);
        double stretch = k;
        if (offset != vec3(0.0) && r2 > min(rm2, rf2) && r2 < rf2) {
            double ab = 1.0 + dot(offset, p.xyz) / r2, aa = dot(p.xyz + offset, p.xyz + offset) / r2;
            double t = 2.0 - 4.0 * ab + 4.0 * aa, d = (1.0 - 2.0 * ab) * (1.0 - 2.0 * ab);
            stretch = k * sqrt(0.5 * (t + sqrt(max(t * t - 4.0 * d, 0.0))));
        }
        p.xyz = (p.xyz + offset) * k - offset;
        p.w *= stretch;
    }
};

}  // namespace fraktal::blocks
