#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The box fold with a limit per axis (Tglad's fold as Mandelbulber2's abox and Amazing Surf
// formulas write it, |v + L| - |v - L| - v per coordinate): clamp(v, -L, L) * 2 - v, z only
// where fold_z is on. A reflection where it folds: distances are kept.
struct BoxFoldAxes {
    static constexpr std::string_view id = "box_fold_axes";
    static constexpr std::string_view label = "Box fold per axis";
    static constexpr std::string_view help =
        "Box fold with its own limit on each axis: reflect each coordinate that leaves [-L, L] back inside.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 4.0, "Folding limits L for x, y and z."},
        toggleParam("fold_z", true, "Off: z is left as it is (a fold of x and y alone)."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 folded = clamp(p.xyz, -limit, limit) * 2.0 - p.xyz;
    p.xyz = vec3(folded.xy, fold_z > 0.5 ? folded.z : p.z);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 limit = a.v3(0);
        const vec3 folded = clamp(p.xyz, -limit, limit) * 2.0 - p.xyz;
        p.xyz = vec3(folded.x, folded.y, a.f(1) > 0.5 ? folded.z : p.xyz.z);
    }
};

}  // namespace fraktal::blocks
