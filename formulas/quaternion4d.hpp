#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's quaternion4d (Quaternion4dIteration in fractal_formulas.cpp of 2.20): the
// quaternion square's real part and its x-y and x-z products on the 4D point (xyz, P4::pointW;
// formulas/four_d.hpp), w kept, each coordinate times its multiplier, then the offset added:
// (x^2 - y^2 - z^2 - w^2, x y, x z, w) m + a. With Mandelbulber2's multipliers (1, 2, 2, 0) the
// xyz part is the quaternion square's and w becomes a's w every iteration.
// The running derivative grows by a bound on the Jacobian's largest singular value: the xyz rows
// are the quaternion square's (whose stretch is 2 |q|) scaled by m_x, m_y / 2 and m_z / 2, and the w
// row is m_w's, so |J dv| <= sqrt(4 k^2 |q|^2 + m_w^2) |dv| with k the largest of |m_x|, |m_y| / 2,
// |m_z| / 2. With the default multipliers that is 2 |q|, Mandelbulber2's own aux.DE factor.
struct Quaternion4d {
    static constexpr std::string_view id = "quaternion4d";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Quaternion 4D";
    static constexpr std::string_view help =
        "The 4D point becomes (x^2 - y^2 - z^2 - w^2, x y, x z, w) times the multipliers, plus the offset "
        "(Mandelbulber2's quaternion4d; multipliers 1, 2, 2, 0: the quaternion square's xyz).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"multiplier", ParamType::Vec3, {1.0, 2.0, 2.0}, -4.0, 4.0, "Multipliers of x, y and z."},
        ParamDecl{"multiplier_w", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "Multiplier of w."},
        ParamDecl{"offset", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Added to x, y and z."},
        ParamDecl{"offset_w", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "Added to w."},
    };

    static constexpr std::string_view glsl = R"(
    vec4 q = vec4(p.xyz, pointW);
    float k = max(abs(multiplier.x), 0.5 * max(abs(multiplier.y), abs(multiplier.z)));
    p.w *= sqrt(4.0 * k * k * dot(q, q) + multiplier_w * multiplier_w);
    p.xyz = vec3(q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w, q.x * q.y, q.x * q.z) * multiplier + offset;
    pointW = q.w * multiplier_w + offset_w;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 multiplier = a.v3(0), offset = a.v3(2);
        const double multiplierW = a.f(1), offsetW = a.f(3);
        const vec4 q(p.xyz, p.pointW);
        const double k =
            std::max(std::abs(multiplier.x), 0.5 * std::max(std::abs(multiplier.y), std::abs(multiplier.z)));
        p.w *= std::sqrt(4.0 * k * k * dot(q, q) + multiplierW * multiplierW);
        p.xyz = vec3(q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w, q.x * q.y, q.x * q.z) * multiplier + offset;
        p.pointW = q.w * multiplierW + offsetW;
    }
};

}  // namespace fraktal::blocks
