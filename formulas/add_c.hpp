#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Add the iteration's starting point c, as in Mandelbrot-type formulas (seed 2.1.3, 2.2.2):
// dp/dc gains 1, so the running derivative does too (PySpace FoldScaleOrigin adds vec4(c, 1)).
// Julia mode adds a fixed constant k instead, v -> f(v) + k, as for the quadratic Julia sets
// (seed 2.1.3) and the Juliabulb (White/Nylander's Mandelbulb with a fixed c). The estimate then
// differentiates with respect to the starting point p0 only: k does not depend on p0, so
// d(p)/d(p0) gains no +1 term (Syntopia, "Distance estimated 3D fractals" part V, Julia sets).
struct AddC {
    static constexpr std::string_view id = "add_c";
    static constexpr std::string_view label = "Add c";
    static constexpr std::string_view help =
        "Add the starting point c (Mandelbrot-type formulas); the derivative gains 1. Julia mode adds a fixed "
        "constant instead.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{
            "weight", ParamType::Float, {1.0, 0.0, 0.0}, -2.0, 2.0, "Multiple of c that is added (not in Julia mode)."},
        toggleParam("julia", false, "On: add the fixed constant julia_c (a Julia set); off: add c (Mandelbrot type)."),
        ParamDecl{"julia_c", ParamType::Vec3, {-0.2, 0.6, 0.2}, -10.0, 10.0, "The constant added in Julia mode."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz += julia > 0.5 ? julia_c : c * weight;
    p.w += julia > 0.5 ? 0.0 : abs(weight);
)";
    static void apply(P4& p, const vec3& c, Args a) {
        const double weight = a.f(0), julia = a.f(1);
        const vec3 julia_c = a.v3(2);
        p.xyz += julia > 0.5 ? julia_c : c * weight;
        p.w += julia > 0.5 ? 0.0 : abs(weight);
    }
};

}  // namespace fraktal::blocks
