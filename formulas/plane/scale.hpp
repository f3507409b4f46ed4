#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// Uniform scale about a centre. Distances in the scaled plane grow by |factor|, so the running
// scale does too (seed 3.2).
struct Scale {
    static constexpr std::string_view id = "scale";
    static constexpr std::string_view label = "Scale";
    static constexpr std::string_view help =
        "Scale about a centre: z = centre + factor (z - centre); the running scale grows by |factor|.";
    static constexpr Category category = Category::Transform;
    static constexpr std::array params{
        ParamDecl{"factor", ParamType::Float, {2.0, 0.0, 0.0}, -10.0, 10.0, "Scale factor."},
        ParamDecl{"center_x", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Fixed point of the scaling, x."},
        ParamDecl{"center_y", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Fixed point of the scaling, y."},
    };

    static constexpr std::string_view glsl = R"(
    real2 o = real2(center_x, center_y);
    s.z = o + real(factor) * (s.z - o);
    s.dz *= real(abs(factor));
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double factor = a.f(0), center_x = a.f(1), center_y = a.f(2);
        real2 o = real2(center_x, center_y);
        s.z = o + real(factor) * (s.z - o);
        s.dz *= real(std::abs(factor));
    }
};

}  // namespace fraktal::plane_blocks
