#pragma once
#include <algorithm>
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Graeme McLaren's sine or cosine (Mandelbulber2's transf_sin_or_cos, TransfSinOrCosIteration in
// fractal_formulas.cpp of 2.20). Each chosen axis v becomes scale sin(m v), or scale cos(m v) where
// its `cos_` toggle is on; an axis not chosen becomes 0. With `divide` each axis is then scaled
// once more and divided by |v| + 1 (Mandelbulber2 applies the scale twice there). The map is
// diagonal, so its stretch is the largest over the axes of |d v' / d v|: |scale m| for the wave,
// |scale|^2 (|m| + 1) with the quotient (the wave is at most 1 and 1 / (|v| + 1) falls at slope at
// most 1). With `mb2_derivative` the running derivative takes |scale| alone, as Mandelbulber2's
// does (its +1 is a derivative_tweak after the block), which the import asks for: the estimate is
// then no bound, and the step factor is measured.
struct SinOrCos {
    static constexpr std::string_view id = "sin_or_cos";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Sine or cosine";
    static constexpr std::string_view help =
        "Each chosen axis becomes scale sin(m v) or scale cos(m v), the others 0; optionally scaled again and "
        "divided by |v| + 1 (Mandelbulber2's transf_sin_or_cos).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::string_view jump =
        "with mb2_derivative its running derivative leaves out the waves' slope (as Mandelbulber2's does), so the "
        "estimate is no bound";
    static DerivativeBound derivativeFor(Args a) {
        return a.f(9) > 0.5 ? DerivativeBound::None : DerivativeBound::Global;
    }
    static constexpr std::array params{
        toggleParam("x", true, "Wave the x axis (off: x becomes 0)."),
        toggleParam("y", true, "Wave the y axis (off: y becomes 0)."),
        toggleParam("z", true, "Wave the z axis (off: z becomes 0)."),
        toggleParam("cos_x", false, "The cosine on x in place of the sine."),
        toggleParam("cos_y", false, "The cosine on y in place of the sine."),
        toggleParam("cos_z", false, "The cosine on z in place of the sine."),
        ParamDecl{"multiplier", ParamType::Vec3, {1.0, 1.0, 1.0}, -10.0, 10.0, "m: multiplies each axis in the wave."},
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "The waves' amplitude."},
        toggleParam("divide", false, "Scale each axis once more and divide it by |v| + 1."),
        toggleParam("mb2_derivative", false,
                    "On: the running derivative takes |scale| alone, as Mandelbulber2's (no bound; the step factor "
                    "is measured)."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz, m = vec3(0.0);
    vec3 on = vec3(x, y, z), useCos = vec3(cos_x, cos_y, cos_z);
    float slope = 0.0;
    for (int k = 0; k < 3; ++k) {
        if (on[k] < 0.5) continue;
        float t = multiplier[k] * v[k];
        m[k] = scale * (useCos[k] > 0.5 ? cos(t) : sin(t));
        float s = abs(scale * multiplier[k]);
        if (divide > 0.5) {
            m[k] *= scale / (abs(v[k]) + 1.0);
            s = scale * scale * (abs(multiplier[k]) + 1.0);
        }
        slope = max(slope, s);
    }
    p.xyz = m;
    p.w *= mb2_derivative > 0.5 ? abs(scale) : slope;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 v = p.xyz, multiplier = a.v3(6);
        const double scale = a.f(7);
        const bool divide = a.f(8) > 0.5;
        vec3 m(0.0);
        double slope = 0.0;
        for (int k = 0; k < 3; ++k) {
            if (a.f(k) <= 0.5) continue;
            const double t = multiplier[k] * v[k];
            m[k] = scale * (a.f(3 + k) > 0.5 ? std::cos(t) : std::sin(t));
            double s = std::abs(scale * multiplier[k]);
            if (divide) {
                m[k] *= scale / (std::abs(v[k]) + 1.0);
                s = scale * scale * (std::abs(multiplier[k]) + 1.0);
            }
            slope = std::max(slope, s);
        }
        p.xyz = m;
        p.w *= a.f(9) > 0.5 ? std::abs(scale) : slope;
    }
};

}  // namespace fraktal::blocks
