#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Aexion's 4D set (Mandelbulber2's "aexion", fractal_formulas.cpp AexionIteration): the point and
// c are first folded into the four coordinates |x + y + z|, |-x - y + z|, |-x + y - z|,
// |x - y - z| (each plus `cadd`), then the orbit runs
// (x, y, z, w) -> (x^2 - y^2 + 2wz, y^2 - x^2 + 2wz, z^2 - w^2 + 2xy, w^2 - z^2 + 2xy) + c.
// Like the hypercomplex set (hypercomplex.hpp) it runs its own 4D orbit from the point the node
// list leaves. The running derivative is Mandelbulber2's own estimate of the stretch,
// dr -> 2 (1.1 r + (|q'| / r - 1.1 r) scale) dr + offset with r = |q| before the step; the
// estimate 0.5 r log r / dr where the orbit escaped, 0 (inside) where it stayed bounded. The
// estimate is no bound: `fraktal check` measures its step factor.
struct AexionEstimator {
    static constexpr std::string_view id = "aexion";
    static constexpr std::string_view label = "Aexion";
    static constexpr std::string_view help =
        "Aexion's 4D set: the point folded into four coordinates, then q -> a quadratic map + c; runs its own orbit.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"cadd", ParamType::Float, {-1.3, 0.0, 0.0}, -5.0, 5.0, "Added to each folded coordinate."}.labelled(
            "Fold offset"),
        ParamDecl{"orbit", ParamType::Float, {12.0, 0.0, 0.0}, 1.0, 1000.0, "Iterations of the orbit."},
        ParamDecl{"escape", ParamType::Float, {10000.0, 0.0, 0.0}, 2.0, 1e7, "Escape radius of the orbit."},
        ParamDecl{"scale",
                  ParamType::Float,
                  {1.0, 0.0, 0.0},
                  -10.0,
                  10.0,
                  "Blend of the stretch estimate: 0 takes 1.1 |q|, 1 takes |q'| / |q|."},
        ParamDecl{"offset", ParamType::Float, {1.0, 0.0, 0.0}, -10.0, 10.0, "Added to the derivative each step."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    vec4 k = vec4(abs(v.x + v.y + v.z), abs(-v.x - v.y + v.z), abs(-v.x + v.y - v.z), abs(v.x - v.y - v.z)) + cadd;
    vec4 q = k;
    float dr = abs(p.w), r = length(v);
    bool escaped = false;
    for (int i = 0; i < int(orbit); ++i) {
        float before = r;
        q = vec4(q.x * q.x - q.y * q.y + 2.0 * q.w * q.z, q.y * q.y - q.x * q.x + 2.0 * q.w * q.z,
                 q.z * q.z - q.w * q.w + 2.0 * q.x * q.y, q.w * q.w - q.z * q.z + 2.0 * q.x * q.y) + k;
        r = length(q);
        dr = 2.0 * (1.1 * before + (r / before - 1.1 * before) * scale) * dr + offset;
        if (r > escape) {
            escaped = true;
            break;
        }
    }
    return escaped ? 0.5 * r * log(r) / dr : 0.0;
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double cadd = a.f(0), orbit = a.f(1), escape = a.f(2), scale = a.f(3), offset = a.f(4);
        const vec3 v = p.xyz;
        const vec4 k = vec4(std::abs(v.x + v.y + v.z), std::abs(-v.x - v.y + v.z), std::abs(-v.x + v.y - v.z),
                            std::abs(v.x - v.y - v.z)) +
                       cadd;
        vec4 q = k;
        double dr = abs(p.w), r = length(v);
        bool escaped = false;
        for (int i = 0; i < int(orbit); ++i) {
            const double before = r;
            q = vec4(q.x * q.x - q.y * q.y + 2.0 * q.w * q.z, q.y * q.y - q.x * q.x + 2.0 * q.w * q.z,
                     q.z * q.z - q.w * q.w + 2.0 * q.x * q.y, q.w * q.w - q.z * q.z + 2.0 * q.x * q.y) +
                k;
            r = length(q);
            dr = 2.0 * (1.1 * before + (r / before - 1.1 * before) * scale) * dr + offset;
            if (r > escape) {
                escaped = true;
                break;
            }
        }
        return escaped ? 0.5 * r * std::log(r) / dr : 0.0;
    }
};

}  // namespace fraktal::blocks
