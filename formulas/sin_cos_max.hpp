#pragma once
#include <algorithm>
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Graeme McLaren's sine and cosine maximum (Mandelbulber2's transf_sin_and_cos_max,
// fractal_formulas.cpp, TransfSinAndCosMaxIteration). Each chosen axis v becomes the largest of a
// sine wave, a cosine wave and their product,
//   a sin(2 pi v / P), b cos(2 pi v / Q), c (a sin)(b cos),
// divided by |v| + 1 when `divide` is on; then every axis is scaled, and v is added or multiplied
// back in by `keep` (1: + v, 2: x v, 3: + |v|, 4: x |v|). The map is diagonal, so its stretch is the
// largest over the axes of a bound of |d v' / d v|: a wave of amplitude A and period P has slope
// at most 2 pi A / P and value at most A; the quotient by |v| + 1 adds the value to the slope.
// Multiplied by v the slope grows with |v|: a bound at the point then.
struct SinCosMax {
    static constexpr std::string_view id = "sin_cos_max";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Sine and cosine maximum";
    static constexpr std::string_view help =
        "Each chosen axis becomes the largest of a sine wave, a cosine wave and their product (Mandelbulber2's "
        "transf_sin_and_cos_max), then scaled; v may be added or multiplied back in.";
    static constexpr Category category = Category::Transform;
    // Global unless v is multiplied back in (keep 2 or 4); the weaker of the two for all.
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        toggleParam("x", true, "Wave the x axis."),
        toggleParam("y", false, "Wave the y axis."),
        toggleParam("z", false, "Wave the z axis."),
        ParamDecl{"sin_period", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.05, 100.0, "The sine wave's period per axis."},
        ParamDecl{"cos_period", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.05, 100.0, "The cosine wave's period per axis."},
        ParamDecl{"sin_scale", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "The sine wave's amplitude."},
        ParamDecl{"cos_scale", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "The cosine wave's amplitude."},
        ParamDecl{"product_scale", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "Multiplies the waves' product."},
        toggleParam("divide", false, "Divide each wave's maximum by |v| + 1."),
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "Scales the result (all axes)."},
        ParamDecl{"keep",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  0.0,
                  4.0,
                  "0: the waves alone; 1: plus v; 2: times v; 3: plus |v|; 4: times |v|."},
    };

    static constexpr std::string_view glsl = R"(
    const float TAU = 6.283185307179586;
    vec3 v = p.xyz, m = v;
    vec3 on = vec3(x, y, z);
    float valueBound = max(max(abs(sin_scale), abs(cos_scale)), abs(product_scale * sin_scale * cos_scale));
    vec3 slope = vec3(1.0), value = abs(v);
    for (int k = 0; k < 3; ++k) {
        if (on[k] < 0.5) continue;
        float a = TAU / sin_period[k], b = TAU / cos_period[k];
        float s = sin_scale * sin(a * v[k]), co = cos_scale * cos(b * v[k]);
        float f = max(max(s, co), product_scale * s * co);
        slope[k] = max(max(abs(sin_scale) * a, abs(cos_scale) * b), abs(product_scale * sin_scale * cos_scale) * (a + b));
        value[k] = valueBound;
        if (divide > 0.5) {
            f /= abs(v[k]) + 1.0;
            slope[k] += valueBound;
        }
        m[k] = f;
    }
    m *= scale;
    slope *= abs(scale);
    value *= abs(scale);
    int keep_ = int(keep + 0.5);
    if (keep_ == 1 || keep_ == 3) {
        m += keep_ == 1 ? v : abs(v);
        slope += 1.0;
    } else if (keep_ == 2 || keep_ == 4) {
        m *= keep_ == 2 ? v : abs(v);
        slope = slope * abs(v) + value;
    }
    p.xyz = m;
    p.w *= max(max(slope.x, slope.y), slope.z);
)";
    static void apply(P4& p, const vec3&, Args a) {
        constexpr double kTau = 6.283185307179586;
        const bool on[3] = {a.f(0) > 0.5, a.f(1) > 0.5, a.f(2) > 0.5};
        const vec3 sinPeriod = a.v3(3), cosPeriod = a.v3(4);
        const double sinScale = a.f(5), cosScale = a.f(6), productScale = a.f(7), scale = a.f(9);
        const bool divide = a.f(8) > 0.5;
        const vec3 v = p.xyz;
        vec3 m = v;
        const double valueBound =
            std::max({std::abs(sinScale), std::abs(cosScale), std::abs(productScale * sinScale * cosScale)});
        vec3 slope(1.0), value = glm::abs(v);
        for (int k = 0; k < 3; ++k) {
            if (!on[k]) continue;
            const double s0 = kTau / sinPeriod[k], c0 = kTau / cosPeriod[k];
            const double s = sinScale * std::sin(s0 * v[k]), co = cosScale * std::cos(c0 * v[k]);
            double f = std::max({s, co, productScale * s * co});
            slope[k] = std::max({std::abs(sinScale) * s0, std::abs(cosScale) * c0,
                                 std::abs(productScale * sinScale * cosScale) * (s0 + c0)});
            value[k] = valueBound;
            if (divide) {
                f /= std::abs(v[k]) + 1.0;
                slope[k] += valueBound;
            }
            m[k] = f;
        }
        m *= scale;
        slope *= std::abs(scale);
        value *= std::abs(scale);
        const int keep = int(std::lround(a.f(10)));
        if (keep == 1 || keep == 3) {
            m += keep == 1 ? v : glm::abs(v);
            slope += 1.0;
        } else if (keep == 2 || keep == 4) {
            m *= keep == 2 ? v : glm::abs(v);
            slope = slope * glm::abs(v) + value;
        }
        p.xyz = m;
        p.w *= std::max({slope.x, slope.y, slope.z});
    }
};

}  // namespace fraktal::blocks
