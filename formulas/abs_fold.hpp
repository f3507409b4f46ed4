#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mirror across the three coordinate planes (p -> |p|): the octant fold of the Menger sponge.
struct AbsFold {
    static constexpr std::string_view id = "abs_fold";
    static constexpr std::string_view label = "Abs fold";
    static constexpr std::string_view help = "Mirror across the three coordinate planes: p = |p|.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    p.xyz = abs(p.xyz);
)";
    static void apply(P4& p, const vec3&, Args) { p.xyz = abs(p.xyz); }
};

}  // namespace fraktal::blocks
