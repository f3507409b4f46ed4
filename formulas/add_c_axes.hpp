#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Add c with a weight per axis (Mandelbulber2's fractal_constant_factor given per axis): the
// derivative gains the largest |weight|, the map's stretch in c; Julia mode adds julia_c. With
// swap_xy the constant's x and y change places (Mandelbulber2 adds c that way after aboxMod1 and
// amazing surf: compute_fractal.cpp); then it is turned by turn_angle about turn_axis (amazing
// surf mod 2 turns its extra c by transf_rotation). A turn keeps |c|: the bound stays.
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
        toggleParam("swap_xy", false,
                    "On: the constant's x and y exchanged first (c or julia_c; Mandelbulber2's aboxMod1 and "
                    "amazing surf)."),
        ParamDecl{"turn_axis", ParamType::Vec3, {0.0, 0.0, 1.0}, -1.0, 1.0, "Axis the constant is turned about.", true},
        ParamDecl{"turn_angle", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Turn of the constant, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 k = julia > 0.5 ? julia_c : c;
    if (swap_xy > 0.5) k = k.yxz;
    if (turn_angle != 0.0) {  // a uniform branch: the unturned constant costs no sine each step
        vec3 n = normalize(turn_axis);
        float s = sin(radians(turn_angle)), co = cos(radians(turn_angle));
        k = k * co + cross(n, k) * s + n * dot(n, k) * (1.0 - co);
    }
    p.xyz += julia > 0.5 ? k : k * weights;
    p.w += julia > 0.5 ? 0.0 : max(abs(weights.x), max(abs(weights.y), abs(weights.z)));
)";
    static void apply(P4& p, const vec3& c, Args a) {
        const vec3 weights = a.v3(0), julia_c = a.v3(2), turn_axis = a.v3(4);
        const double julia = a.f(1), swap_xy = a.f(3), turn_angle = a.f(5);
        vec3 k = julia > 0.5 ? julia_c : c;
        if (swap_xy > 0.5) k = vec3(k.y, k.x, k.z);
        if (turn_angle != 0.0) {  // a uniform branch: the unturned constant costs no sine each step
            vec3 n = normalize(turn_axis);
            double s = sin(glm::radians(turn_angle)), co = cos(glm::radians(turn_angle));
            k = k * co + glm::cross(n, k) * s + n * dot(n, k) * (1.0 - co);
        }
        p.xyz += julia > 0.5 ? k : k * weights;
        p.w += julia > 0.5 ? 0.0 : max(abs(weights.x), max(abs(weights.y), abs(weights.z)));
    }
};

}  // namespace fraktal::blocks
