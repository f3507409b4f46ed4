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
        toggleParam("x", true, "On: x = |x|; off: leave x."),
        toggleParam("y", false, "On: y = |y|; off: leave y."),
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
