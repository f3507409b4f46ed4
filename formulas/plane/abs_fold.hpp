#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// Mirror across the coordinate axes: z.x = |z.x| folds across the y axis (and likewise for y).
struct AbsFold {
    static constexpr std::string_view id = "abs_fold";
    static constexpr std::string_view label = "Abs fold";
    static constexpr std::string_view help = "Mirror across the y axis (x = |x|) and/or the x axis (y = |y|).";
    static constexpr Category category = Category::Fold;
    static constexpr std::array params{
        ParamDecl{"x", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 1.0, "1: x = |x|; 0: leave x."},
        ParamDecl{"y", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 1.0, "1: y = |y|; 0: leave y."},
    };

    static constexpr std::string_view glsl = R"(
    if (x > 0.5) s.z.x = abs(s.z.x);
    if (y > 0.5) s.z.y = abs(s.z.y);
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double x = a.f(0), y = a.f(1);
        if (x > 0.5) s.z.x = std::abs(s.z.x);
        if (y > 0.5) s.z.y = std::abs(s.z.y);
    }
};

}  // namespace fraktal::plane_blocks
