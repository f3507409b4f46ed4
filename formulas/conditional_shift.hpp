#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Each axis shifted back where it lies above its threshold: v_k - shift_k where v_k > threshold_k
// (the conditional shifts of an IFS step that keeps one cell of a grid, such as Mandelbulber2's
// Vicsek, VicsekIteration in fractal_formulas.cpp of 2.20). Shifts keep distances, but the map
// jumps at each threshold.
struct ConditionalShift {
    static constexpr std::string_view id = "conditional_shift";
    static constexpr std::string_view label = "Conditional shift";
    static constexpr std::string_view help =
        "Each axis above its threshold is shifted back by its shift (an IFS step's move into one grid cell).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where an axis crosses its threshold";
    static constexpr std::array params{
        ParamDecl{"threshold", ParamType::Vec3, {0.5, 0.5, 1.0}, -20.0, 20.0, "Above this an axis is shifted back."},
        ParamDecl{"shift", ParamType::Vec3, {1.0, 1.0, 2.0}, -40.0, 40.0, "How far each axis is shifted back."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz -= mix(vec3(0.0), shift, greaterThan(p.xyz, threshold));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 threshold = a.v3(0), shift = a.v3(1);
        for (int k = 0; k < 3; ++k)
            if (p.xyz[k] > threshold[k]) p.xyz[k] -= shift[k];
    }
};

}  // namespace fraktal::blocks
