#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Add c with a weight per axis (Mandelbulber2's fractal_constant_factor given per axis): the
// derivative gains the largest |weight|, the map's stretch in c; Julia mode adds julia_c.
struct AddCAxes {
    static constexpr std::string_view id = "add_c_axes";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Add c per axis";
    static constexpr std::string_view help =
        "Add c times a weight per axis; the derivative gains the largest weight. Julia mode adds julia_c instead.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{
            "weights", ParamType::Vec3, {1.0, 1.0, 1.0}, -2.0, 2.0, "Multiple of c per axis (not in Julia mode)."},
        toggleParam("julia", false, "On: add the fixed constant julia_c (a Julia set); off: add c (Mandelbrot type)."),
        ParamDecl{"julia_c", ParamType::Vec3, {-0.2, 0.6, 0.2}, -10.0, 10.0, "The constant added in Julia mode."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz += julia > 0.5 ? julia_c : c * weights;
    p.w += julia > 0.5 ? 0.0 : max(abs(weights.x), max(abs(weights.y), abs(weights.z)));
)";
    static void apply(P4& p, const vec3& c, Args a) {
        const vec3 weights = a.v3(0), julia_c = a.v3(2);
        const double julia = a.f(1);
        p.xyz += julia > 0.5 ? julia_c : c * weights;
        p.w += julia > 0.5 ? 0.0 : max(abs(weights.x), max(abs(weights.y), abs(weights.z)));
    }
};

}  // namespace fraktal::blocks
