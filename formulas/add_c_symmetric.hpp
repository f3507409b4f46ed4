#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Add a multiple of c signed by the point (Mandelbulber2's "add Cpixel symmetrical":
// TransfAddCpixelSymmetricalIteration, and the option of abox_mod_kali_v2 and
// pseudo_kleinian_mod2): v + sign(v) k per axis, k = weights c with c's abs taken on the axes
// abs_axes names. The term pushes each coordinate away from its axis plane, so the map jumps
// where a coordinate changes sign; elsewhere it is v plus a term of c alone, whose stretch in c
// is at most the largest |weight| (the derivative gains that, as with add_c_axes).
struct AddCSymmetric {
    static constexpr std::string_view id = "add_c_symmetric";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Add c signed by the point";
    static constexpr std::string_view help =
        "Add c times a weight per axis, signed like the point on each axis (c's abs taken on the chosen axes).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where a coordinate of the point changes sign";
    static constexpr std::array params{
        ParamDecl{"weights", ParamType::Vec3, {0.0, 0.0, 0.0}, -2.0, 2.0, "Multiple of c per axis."},
        ParamDecl{"abs_axes", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 1.0, "Per axis, 1 takes |c| (0 keeps c's sign)."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 k = mix(c, abs(c), step(0.5, abs_axes)) * weights;
    p.xyz += sign(p.xyz) * k;
    p.w += max(abs(weights.x), max(abs(weights.y), abs(weights.z)));
)";
    static void apply(P4& p, const vec3& c, Args a) {
        const vec3 weights = a.v3(0), abs_axes = a.v3(1);
        vec3 k = glm::mix(c, abs(c), glm::step(vec3(0.5), abs_axes)) * weights;
        p.xyz += glm::sign(p.xyz) * k;
        p.w += max(abs(weights.x), max(abs(weights.y), abs(weights.z)));
    }
};

}  // namespace fraktal::blocks
