#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Translation keeps distances (seed 3.2): the running scale is unchanged.
struct Translate {
    static constexpr std::string_view id = "translate";
    static constexpr std::string_view label = "Translate";
    static constexpr std::string_view help = "Move the point by a fixed offset (a Julia-style constant).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"offset", ParamType::Vec3, {0.0, 0.0, 0.0}, -20.0, 20.0, "Offset added to p."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz += offset;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 offset = a.v3(0);
        p.xyz += offset;
    }
};

}  // namespace fraktal::blocks
