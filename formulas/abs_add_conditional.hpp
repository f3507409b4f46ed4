#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's transf_abs_add_conditional (fractal_formulas.cpp
// TransfAbsAddConditionalIteration): on each enabled axis, x -> sign(x) (offset - |x| + m |x|),
// which pushes the two half-spaces apart by the offset (or pulls them together) and scales each
// by m - 1. It jumps across the axis plane where the offset is not 0; the running derivative is
// the largest |m - 1| of the enabled axes (1 for the others).
struct AbsAddConditional {
    static constexpr std::string_view id = "abs_add_conditional";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Abs add conditional";
    static constexpr std::string_view help =
        "Per enabled axis, x -> sign(x) (offset - |x| + m |x|): the half-spaces shifted apart and scaled.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps across each enabled axis plane by twice the offset";
    static constexpr std::array params{
        ParamDecl{"axes", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 1.0, "Per axis, 1 applies the step (0 leaves it)."},
        ParamDecl{
            "offset", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "Added to each side's distance from the plane."},
        ParamDecl{"multiplier", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "m: |x| comes back as (m - 1) |x|."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 on = step(0.5, axes);
    p.xyz = mix(p.xyz, sign(p.xyz) * (offset - abs(p.xyz) + abs(p.xyz) * multiplier), on);
    vec3 stretch = mix(vec3(1.0), abs(multiplier - 1.0), on);
    p.w *= max(stretch.x, max(stretch.y, stretch.z));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 axes = a.v3(0), offset = a.v3(1), multiplier = a.v3(2);
        vec3 on = glm::step(vec3(0.5), axes);
        p.xyz = glm::mix(p.xyz, glm::sign(p.xyz) * (offset - glm::abs(p.xyz) + glm::abs(p.xyz) * multiplier), on);
        vec3 stretch = glm::mix(vec3(1.0), glm::abs(multiplier - 1.0), on);
        p.w *= max(stretch.x, max(stretch.y, stretch.z));
    }
};

}  // namespace fraktal::blocks
