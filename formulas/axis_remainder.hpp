#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// The remainder of chosen coordinates after division, with the sign of the coordinate (C's fmod,
// truncating towards zero): mancoast's modulus operation, which Mandelbulber2's
// modulus_mandelbulb applies to y after the Mandelbulb's power (fractal_formulas.cpp
// ModulusMandelbulbIteration, 2.20; reference: fractalforums.com, "escape-time algorithm defined
// using the quotient and remainder functions"). Between the jumps it is a translation, so it
// stretches nothing: the running derivative is unchanged, as Mandelbulber2 leaves it. Unlike
// `mod_tile` (cells centred on the origin) the remainder keeps the sign and reaches from -d to d,
// and an axis with divisor 0 is left as it is.
struct AxisRemainder {
    static constexpr std::string_view id = "axis_remainder";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Remainder per axis";
    static constexpr std::string_view help =
        "Each coordinate with a divisor above 0 becomes its remainder after division by it, keeping its sign "
        "(fmod: from -divisor to divisor); divisor 0 leaves the axis (Mandelbulber2's modulus operation).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where a coordinate passes a multiple of its divisor";
    static constexpr std::array params{
        ParamDecl{"divisor",
                  ParamType::Vec3,
                  {0.0, 2.0, 0.0},
                  0.0,
                  40.0,
                  "Divisor per axis (x, y, z); 0 leaves that coordinate as it is."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 d = max(divisor, vec3(1e-30));
    p.xyz = mix(p.xyz, p.xyz - d * trunc(p.xyz / d), greaterThan(divisor, vec3(0.0)));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 divisor = a.v3(0);
        for (int k = 0; k < 3; ++k)
            if (divisor[k] > 0.0) p.xyz[k] = std::fmod(p.xyz[k], divisor[k]);
    }
};

}  // namespace fraktal::blocks
