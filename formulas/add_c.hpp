#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Add the iteration's starting point c, as in Mandelbrot-type formulas (seed 2.1.3, 2.2.2):
// dp/dc gains 1, so the running derivative does too (PySpace FoldScaleOrigin adds vec4(c, 1)).
struct AddC {
    static constexpr std::string_view id = "add_c";
    static constexpr std::string_view label = "Add c";
    static constexpr std::string_view help =
        "Add the starting point c (Mandelbrot-type formulas); the derivative gains 1.";
    static constexpr Category category = Category::Transform;
    static constexpr std::array params{
        ParamDecl{"weight", ParamType::Float, {1.0, 0.0, 0.0}, -2.0, 2.0, "Multiple of c that is added."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz += c * weight;
    p.w += abs(weight);
)";
    static void apply(P4& p, const vec3& c, Args a) {
        const double weight = a.f(0);
        p.xyz += c * weight;
        p.w += abs(weight);
    }
};

}  // namespace fraktal::blocks
