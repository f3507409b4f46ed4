#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The scator square (Manuel Fernandez-Guasti's scators; Mandelbulber2's scator_power2,
// ScatorPower2Iteration in formula/opencl/scator_power2.cl of 2.20). Real form: (x^2 + y^2 + z^2,
// x y, x z), times `multiplier` per axis, then x gains y^2 z^2 / x^2 and y and z are multiplied by
// 1 + z^2 / x^2 and 1 + y^2 / x^2. Imaginary form: x^2 - y^2 - z^2 and the factors 1 - z^2 / x^2,
// 1 - y^2 / x^2. The terms over x^2 blow up at the plane x = 0 (x^2 is held above 1e-30 so that
// the orbit escapes there rather than turning into NaN). The running derivative takes
// Mandelbulber2's 2 r, r the scator magnitude (x^2 + y^2 + z^2 + y^2 z^2 / x^2)^(1/2) of the point
// (Mandelbulber2 measures a scator orbit by it: compute_fractal.cl), or with `ratio` the larger
// of that and 2 ratio_scale |v'| / |v| (its "vector DE"): estimates, so `fraktal check` measures
// the step factor.
struct ScatorSquare {
    static constexpr std::string_view id = "scator_power2";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Scator square";
    static constexpr std::string_view help =
        "The scator square: x against y and z with terms over x^2 (real or imaginary form), per-axis "
        "multiplier; spiky shapes along x.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its terms over x^2 blow up at the plane x = 0";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        toggleParam("imaginary", false, "On: the imaginary scator (x^2 - y^2 - z^2); off: the real one."),
        ParamDecl{"multiplier", ParamType::Vec3, {1.0, 2.0, 2.0}, -4.0, 4.0, "Multiplies the square per axis."},
        toggleParam("ratio", false,
                    "On: the derivative grows by at least twice ratio_scale times how much the step stretched |v|.")
            .labelled("Derivative from the stretch"),
        ParamDecl{"ratio_scale", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "Weight of the stretch (with ratio)."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz, q = v * v;
    float sg = imaginary > 0.5 ? -1.0 : 1.0, x2 = max(q.x, 1e-30);
    vec3 n = vec3(q.x + sg * (q.y + q.z), v.x * v.y, v.x * v.z) * multiplier;
    n += vec3(q.y * q.z / x2, 0.0, 0.0);
    n.yz *= vec2(1.0 + sg * q.z / x2, 1.0 + sg * q.y / x2);
    float r = sqrt(q.x + q.y + q.z + q.y * q.z / x2), len = length(v);
    p.w *= 2.0 * (ratio > 0.5 && len > 0.0 ? max(r, ratio_scale * length(n) / len) : r);
    p.xyz = n;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 multiplier = a.v3(1);
        const double imaginary = a.f(0), ratio = a.f(2), ratio_scale = a.f(3);
        const vec3 v = p.xyz, q = v * v;
        const double sg = imaginary > 0.5 ? -1.0 : 1.0, x2 = std::max(q.x, 1e-30);
        vec3 n = vec3(q.x + sg * (q.y + q.z), v.x * v.y, v.x * v.z) * multiplier;
        n.x += q.y * q.z / x2;
        n.y *= 1.0 + sg * q.z / x2;
        n.z *= 1.0 + sg * q.y / x2;
        const double r = std::sqrt(q.x + q.y + q.z + q.y * q.z / x2), len = length(v);
        p.w *= 2.0 * (ratio > 0.5 && len > 0.0 ? std::max(r, ratio_scale * length(n) / len) : r);
        p.xyz = n;
    }
};

}  // namespace fraktal::blocks
