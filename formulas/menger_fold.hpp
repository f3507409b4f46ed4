#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Sort the coordinates so that x >= y >= z by three mirrors across the planes x=y, x=z, y=z
// (Knighty's Menger fold, as in PySpace FoldMenger). Mirrors keep distances (seed 3.2).
struct MengerFold {
    static constexpr std::string_view id = "menger_fold";
    static constexpr std::string_view label = "Menger fold";
    static constexpr std::string_view help = "Mirror across x=y, x=z and y=z so that x >= y >= z.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float a = min(p.x - p.y, 0.0); p.x -= a; p.y += a;
    a = min(p.x - p.z, 0.0); p.x -= a; p.z += a;
    a = min(p.y - p.z, 0.0); p.y -= a; p.z += a;
)";
    static void apply(P4& p, const vec3&, Args) {
        double a = min(p.xyz.x - p.xyz.y, 0.0);
        p.xyz.x -= a;
        p.xyz.y += a;
        a = min(p.xyz.x - p.xyz.z, 0.0);
        p.xyz.x -= a;
        p.xyz.z += a;
        a = min(p.xyz.y - p.xyz.z, 0.0);
        p.xyz.y -= a;
        p.xyz.z += a;
    }
};

}  // namespace fraktal::blocks
