#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Translation keeps distances (seed 3.2): the running scale is unchanged. `offset_w` moves the
// point's fourth coordinate (P4::pointW), which the 4D steps carry (formulas/four_d.hpp).
struct Translate {
    static constexpr std::string_view id = "translate";
    static constexpr std::string_view label = "Translate";
    static constexpr std::string_view help = "Move the point by a fixed offset (a Julia-style constant).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"offset", ParamType::Vec3, {0.0, 0.0, 0.0}, -20.0, 20.0, "Offset added to p."},
        ParamDecl{"offset_w",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -20.0,
                  20.0,
                  "Added to the point's fourth coordinate w, which the 4D steps read."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz += offset;
    pointW += offset_w;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 offset = a.v3(0);
        const double offset_w = a.f(1);
        p.xyz += offset;
        p.pointW += offset_w;
    }
};

}  // namespace fraktal::blocks
