#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// Translation keeps distances (seed 3.2).
struct Translate {
    static constexpr std::string_view id = "translate";
    static constexpr std::string_view label = "Translate";
    static constexpr std::string_view help = "Add a fixed offset to z.";
    static constexpr Category category = Category::Transform;
    static constexpr std::array params{
        ParamDecl{"x", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Offset, x."},
        ParamDecl{"y", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Offset, y."},
    };

    static constexpr std::string_view glsl = R"(
    s.z += real2(x, y);
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double x = a.f(0), y = a.f(1);
        s.z += real2(x, y);
    }
};

}  // namespace fraktal::plane_blocks
