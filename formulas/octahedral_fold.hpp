#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Octahedral fold of Knighty's kaleidoscopic IFS (Syntopia, "Distance estimated 3D fractals
// part III"): mirrors across x+y=0, x+z=0, x-y=0 and x-z=0.
struct OctahedralFold {
    static constexpr std::string_view id = "octahedral_fold";
    static constexpr std::string_view label = "Octahedral fold";
    static constexpr std::string_view help = "Octahedral fold: mirror across x+y=0, x+z=0, x=y and x=z.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float a = min(p.x + p.y, 0.0); p.x -= a; p.y -= a;
    a = min(p.x + p.z, 0.0); p.x -= a; p.z -= a;
    a = min(p.x - p.y, 0.0); p.x -= a; p.y += a;
    a = min(p.x - p.z, 0.0); p.x -= a; p.z += a;
)";
    static void apply(P4& p, const vec3&, Args) {
        double a = min(p.xyz.x + p.xyz.y, 0.0);
        p.xyz.x -= a;
        p.xyz.y -= a;
        a = min(p.xyz.x + p.xyz.z, 0.0);
        p.xyz.x -= a;
        p.xyz.z -= a;
        a = min(p.xyz.x - p.xyz.y, 0.0);
        p.xyz.x -= a;
        p.xyz.y += a;
        a = min(p.xyz.x - p.xyz.z, 0.0);
        p.xyz.x -= a;
        p.xyz.z += a;
    }
};

}  // namespace fraktal::blocks
