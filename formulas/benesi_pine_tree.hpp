#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Benesi's pine tree (Mandelbulber2's "benesi_pine_tree", fractal_formulas.cpp
// BenesiPineTreeIteration): with t = 2x / sqrt(y^2 + z^2) (1 on the x axis),
// (x^2 - y^2 - z^2, 2 t y z, t (y^2 - z^2)) + (m.x c.x, m.z c.z, m.y c.y) (c's y and z swapped, each
// scaled by `multiplier`), then turned by `angle` about x. It adds c itself; the running derivative
// is Mandelbulber2's 2 |v| dr + 1 (|v'| = |v|^2 before c: the doubled angle's stretch is
// estimated, not bounded, so `fraktal check` measures the step factor).
struct BenesiPineTree {
    static constexpr std::string_view id = "benesi_pine_tree";
    static constexpr std::string_view label = "Benesi pine tree";
    static constexpr std::string_view help =
        "Benesi's pine tree square plus c (y and z swapped, scaled per axis), turned about x.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"multiplier",
                  ParamType::Vec3,
                  {1.0, 0.0, 0.0},
                  -4.0,
                  4.0,
                  "c's multiple per axis (Mandelbulber2's default adds c.x alone)."},
        ParamDecl{"angle", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Turn about x after the step, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz, k = c * multiplier;
    float yz = v.y * v.y + v.z * v.z, t = yz > 0.0 ? 2.0 * v.x / sqrt(yz) : 1.0;
    p.w = 2.0 * length(v) * p.w + 1.0;
    p.xyz = vec3(v.x * v.x - yz + k.x, 2.0 * t * v.y * v.z + k.z, t * (v.y * v.y - v.z * v.z) + k.y);
    float b = radians(angle), y = p.y;
    p.y = y * cos(b) + p.z * sin(b);
    p.z = -y * sin(b) + p.z * cos(b);
)";
    static void apply(P4& p, const vec3& c, Args a) {
        const vec3 multiplier = a.v3(0);
        const double angle = a.f(1);
        const vec3 v = p.xyz, k = c * multiplier;
        double yz = v.y * v.y + v.z * v.z, t = yz > 0.0 ? 2.0 * v.x / std::sqrt(yz) : 1.0;
        p.w = 2.0 * length(v) * p.w + 1.0;
        p.xyz = vec3(v.x * v.x - yz + k.x, 2.0 * t * v.y * v.z + k.z, t * (v.y * v.y - v.z * v.z) + k.y);
        double b = glm::radians(angle), y = p.xyz.y;
        p.xyz.y = y * cos(b) + p.xyz.z * sin(b);
        p.xyz.z = -y * sin(b) + p.xyz.z * cos(b);
    }
};

}  // namespace fraktal::blocks
