#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's "DE tweak" (analyticDE_scale_1 and analyticDE_offset_1 of its transforms, e.g.
// TransfAbsAddConditionalIteration's aux.DE *= scale1): the running derivative w -> w scale +
// offset, the point left as it is. An artist's control of the surface's thickness at a hit
// threshold: above 1 (or with an offset above 0) the estimate only shrinks, so it stays a bound;
// below, w no longer bounds the map's stretch, the estimate may overshoot, and the step factor is
// measured (`fraktal check`), not proven.
struct DerivativeTweak {
    static constexpr std::string_view id = "derivative_tweak";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Derivative tweak";
    static constexpr std::string_view help =
        "Scale the running derivative (and add an offset) without moving the point: below 1 the surface thins "
        "at the same hit threshold, and the step factor is measured rather than proven.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "it lowers the running derivative below the map's stretch (scale under 1 or offset under 0), so the "
        "estimate is no bound";
    static DerivativeBound derivativeFor(Args a) {
        return a.f(0) >= 1.0 && a.f(1) >= 0.0 ? DerivativeBound::Global : DerivativeBound::None;
    }
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Multiplies the running derivative."},
        ParamDecl{"offset", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Added to it after the scale."},
    };

    static constexpr std::string_view glsl = R"(
    p.w = p.w * scale + offset;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), offset = a.f(1);
        p.w = p.w * scale + offset;
    }
};

}  // namespace fraktal::blocks
