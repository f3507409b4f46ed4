#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Luca GN's inverse cylindrical coordinates (Mandelbulber2's transf_inv_cylindrical,
// TransfInvCylindricalIteration in fractal_formulas.cpp of 2.20; reference fractalforums.com,
// "custom formulas and transforms release"): x read as a radius and y as an angle, the point
// becomes (x cos(s y), x sin(s y), z_scale z) times `scale_all`. Its Jacobian in the xy plane has
// the singular values 1 and |s x| (the angle's stretch grows with the radius), so the running
// derivative grows by |scale_all| max(1, |s x|, |z_scale|) at the point. With `mb2_derivative` it
// takes |scale_all| alone, as Mandelbulber2's does, which the import asks for: with the bound the
// estimate far from Mandelbulber2's inverse-reciprocal-iqbulb example was 30 times smaller and
// its rays ran out of steps before they reached the object (bench/import/README.md). The estimate
// is then no bound, and the step factor is measured.
struct InvCylindrical {
    static constexpr std::string_view id = "inv_cylindrical";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Inverse cylindrical";
    static constexpr std::string_view help =
        "x read as a radius and y as an angle: the point becomes (x cos(s y), x sin(s y), z_scale z) times "
        "scale_all (Mandelbulber2's inverse cylindrical transform).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::string_view jump =
        "with mb2_derivative its running derivative leaves out the angle's stretch |s x| (as Mandelbulber2's does), "
        "so the estimate is no bound";
    // Its stretch |s x| grows with the radius (the fit keeps such a stack's bailout low).
    static constexpr bool stretchGrowsWithRadius = true;
    static DerivativeBound derivativeFor(Args a) {
        return a.f(3) > 0.5 ? DerivativeBound::None : DerivativeBound::Local;
    }
    static constexpr std::array params{
        ParamDecl{"angle_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "s: multiplies y as an angle."},
        ParamDecl{"z_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies z."},
        ParamDecl{"scale_all", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the result."},
        toggleParam("mb2_derivative", false,
                    "On: the running derivative takes |scale_all| alone, as Mandelbulber2's (no bound; the step "
                    "factor is measured)."),
    };

    static constexpr std::string_view glsl = R"(
    float t = angle_scale * p.y;
    p.w *= abs(scale_all) * (mb2_derivative > 0.5 ? 1.0 : max(max(1.0, abs(angle_scale * p.x)), abs(z_scale)));
    p.xyz = vec3(p.x * cos(t), p.x * sin(t), z_scale * p.z) * scale_all;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double s = a.f(0), zScale = a.f(1), scaleAll = a.f(2);
        const double t = s * p.xyz.y;
        p.w *= std::abs(scaleAll) *
               (a.f(3) > 0.5 ? 1.0 : std::max(std::max(1.0, std::abs(s * p.xyz.x)), std::abs(zScale)));
        p.xyz = vec3(p.xyz.x * std::cos(t), p.xyz.x * std::sin(t), zScale * p.xyz.z) * scaleAll;
    }
};

}  // namespace fraktal::blocks
