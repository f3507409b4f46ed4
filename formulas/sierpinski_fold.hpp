#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Tetrahedral fold: mirror across the planes x+y=0, x+z=0, y+z=0 (PySpace FoldSierpinski), which
// maps space onto the side of the tetrahedron vertex (1, 1, 1).
struct SierpinskiFold {
    static constexpr std::string_view id = "sierpinski_fold";
    static constexpr std::string_view label = "Sierpinski fold";
    static constexpr std::string_view help = "Tetrahedral fold: mirror across x+y=0, x+z=0 and y+z=0.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float a = min(p.x + p.y, 0.0); p.x -= a; p.y -= a;
    a = min(p.x + p.z, 0.0); p.x -= a; p.z -= a;
    a = min(p.y + p.z, 0.0); p.y -= a; p.z -= a;
)";
    static void apply(P4& p, const vec3&, Args) {
        double a = min(p.xyz.x + p.xyz.y, 0.0);
        p.xyz.x -= a;
        p.xyz.y -= a;
        a = min(p.xyz.x + p.xyz.z, 0.0);
        p.xyz.x -= a;
        p.xyz.z -= a;
        a = min(p.xyz.y + p.xyz.z, 0.0);
        p.xyz.y -= a;
        p.xyz.z -= a;
    }
};

}  // namespace fraktal::blocks
