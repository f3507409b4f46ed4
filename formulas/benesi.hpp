#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Benesi's power 2 (Mandelbulber2's "benesi", fractal_formulas.cpp BenesiIteration): the x axis
// squared against the (y, z) plane, whose angle doubles: with r1 = y^2 + z^2,
// (x^2 - r1, -2|x| (y^2 - z^2) / sqrt(r1), -4|x| y z / sqrt(r1)), x's term negated where c.x >= 0
// and x >= sqrt(r1) (both branches are 0 where they meet, so the map is continuous). |v'| = |v|^2,
// and the running derivative takes Mandelbulber2's 2 |v|: the stretch of the doubled angles is
// estimated, not bounded, so `fraktal check` measures the step factor.
struct BenesiPow2 {
    static constexpr std::string_view id = "benesi_pow2";
    static constexpr std::string_view label = "Benesi power 2";
    static constexpr std::string_view help =
        "Benesi's square: x against the (y, z) plane, whose angle doubles; mirrored where c.x >= 0.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float r1 = v.y * v.y + v.z * v.z, root = max(sqrt(r1), 1e-20);
    float x = c.x < 0.0 || v.x < sqrt(r1) ? v.x * v.x - r1 : -v.x * v.x + r1;
    float s = -2.0 * abs(v.x) / root;
    p.w *= 2.0 * length(v);
    p.xyz = vec3(x, s * (v.y * v.y - v.z * v.z), s * 2.0 * v.y * v.z);
)";
    static void apply(P4& p, const vec3& c, Args) {
        const vec3 v = p.xyz;
        double r1 = v.y * v.y + v.z * v.z, root = std::max(std::sqrt(r1), 1e-20);
        double x = c.x < 0.0 || v.x < std::sqrt(r1) ? v.x * v.x - r1 : -v.x * v.x + r1;
        double s = -2.0 * abs(v.x) / root;
        p.w *= 2.0 * length(v);
        p.xyz = vec3(x, s * (v.y * v.y - v.z * v.z), s * 2.0 * v.y * v.z);
    }
};

}  // namespace fraktal::blocks
