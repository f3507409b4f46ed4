#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The scale of a Menger step without its folds (Mandelbulber2's kaleidoscopic IFS in Menger
// sponge mode): p = p * s, x and y shifted back by the offset corner's (s - 1) multiple, z only
// where it lies above the middle layer. Shifts keep distances: the running scale grows by |s|.
struct MengerScale {
    static constexpr std::string_view id = "menger_scale";
    static constexpr std::string_view label = "Menger scale";
    static constexpr std::string_view help =
        "Scale s about the offset corner for x and y; z shifts back only above the middle layer (Menger mode).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where it shifts z back above the middle layer";
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {3.0, 0.0, 0.0}, -4.0, 4.0, "Scale s per iteration."},
        ParamDecl{"offset", ParamType::Vec3, {1.0, 1.0, 1.0}, -20.0, 20.0, "Corner the scaling keeps fixed."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz *= scale;
    p.xy -= offset.xy * (scale - 1.0);
    if (p.z > 0.5 * offset.z * (scale - 1.0)) p.z -= offset.z * (scale - 1.0);
    p.w *= abs(scale);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0);
        const vec3 offset = a.v3(1);
        p.xyz *= scale;
        p.xyz.x -= offset.x * (scale - 1.0);
        p.xyz.y -= offset.y * (scale - 1.0);
        if (p.xyz.z > 0.5 * offset.z * (scale - 1.0)) p.xyz.z -= offset.z * (scale - 1.0);
        p.w *= abs(scale);
    }
};

}  // namespace fraktal::blocks
