#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's platonic solid transform (fractal_formulas.cpp, TransfPlatonicSolidIteration): v
// scaled by f = A theta + rho, where
//   theta = cos(F x) sin(F y) + cos(F y) sin(F z) + cos(F z) sin(F x)
// is a triply periodic wave whose level sets carve a platonic-looking cell (its abs with
// abs_wave), and rho = root sqrt(r) + linear r + square r^2 of r = |v| (its first mode is
// rho = rhoMul sqrt(r); its second mode blends the powers). The map is v f(v), with Jacobian
// f I + v grad(f)^T, whose stretch is at most |f| + r |grad f|: a bound at the point.
struct PlatonicSolid {
    static constexpr std::string_view id = "platonic_solid";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Platonic solid";
    static constexpr std::string_view help =
        "Scale the point by a periodic wave of it plus powers of its length (Mandelbulber2's "
        "transf_platonic_solid).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"frequency", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "F: the wave's frequency."},
        ParamDecl{"amplitude", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "A: the wave's weight."},
        toggleParam("abs_wave", false, "On: the wave's abs |theta|."),
        ParamDecl{"root", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "Weight of sqrt(|v|)."},
        ParamDecl{"linear", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Weight of |v|."},
        ParamDecl{"square", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Weight of |v|^2."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float r = length(v), F = frequency;
    vec3 s = sin(F * v), co = cos(F * v);
    float theta = co.x * s.y + co.y * s.z + co.z * s.x;
    vec3 gradTheta = F * vec3(co.z * co.x - s.x * s.y, co.x * co.y - s.y * s.z, co.y * co.z - s.z * s.x);
    if (abs_wave > 0.5 && theta < 0.0) {
        theta = -theta;
        gradTheta = -gradTheta;
    }
    float f = amplitude * theta + root * sqrt(r) + linear * r + square * r * r;
    vec3 gradRho = r > 0.0 ? v * (root / (2.0 * r * sqrt(r)) + linear / r + 2.0 * square) : vec3(0.0);
    p.xyz = v * f;
    p.w *= abs(f) + r * length(amplitude * gradTheta + gradRho);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double frequency = a.f(0), amplitude = a.f(1), abs_wave = a.f(2), root = a.f(3), linear = a.f(4),
                     square = a.f(5);
        vec3 v = p.xyz;
        double r = length(v), F = frequency;
        vec3 s = glm::sin(F * v), co = glm::cos(F * v);
        double theta = co.x * s.y + co.y * s.z + co.z * s.x;
        vec3 gradTheta = F * vec3(co.z * co.x - s.x * s.y, co.x * co.y - s.y * s.z, co.y * co.z - s.z * s.x);
        if (abs_wave > 0.5 && theta < 0.0) {
            theta = -theta;
            gradTheta = -gradTheta;
        }
        double f = amplitude * theta + root * std::sqrt(r) + linear * r + square * r * r;
        vec3 gradRho = r > 0.0 ? v * (root / (2.0 * r * std::sqrt(r)) + linear / r + 2.0 * square) : vec3(0.0);
        p.xyz = v * f;
        p.w *= abs(f) + r * length(amplitude * gradTheta + gradRho);
    }
};

}  // namespace fraktal::blocks
