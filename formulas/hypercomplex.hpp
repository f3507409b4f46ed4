#pragma once
#include "core/block.hpp"
#include "formulas/quaternion.hpp"

namespace fraktal::blocks {

// David Makin's hypercomplex Mandelbrot set (Mandelbulber2's "hypercomplex"): the orbit of
// q -> q^2 + c in the commutative hypercomplex numbers, whose square of (x, y, z, w) is
// (x^2 - y^2 - z^2 - w^2, 2xy - 2wz, 2xz - 2yw, 2xw - 2yz), c = (point, slice). Like the
// quaternion sets (quaternion.hpp) it runs its own 4D orbit from the point the node list leaves,
// with the estimate 0.5 |q| (log|q| - 2^(i - n) log(escape)) / |dq| of K_n's surface and the
// running derivative |dq| -> 2 |q| |dq| + |p.w|. The hypercomplex product does not keep norms,
// so 2 |q| is Mandelbulber2's estimate of the stretch, not a bound: `fraktal check` measures it.
inline vec4 hypercomplexSquare(const vec4& q) {
    return vec4(q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w, 2.0 * (q.x * q.y - q.w * q.z),
                2.0 * (q.x * q.z - q.y * q.w), 2.0 * (q.x * q.w - q.y * q.z));
}

struct HypercomplexMandelbrot {
    static constexpr std::string_view id = "hypercomplex_mandelbrot";
    static constexpr std::string_view label = "Hypercomplex Mandelbrot";
    static constexpr std::string_view help =
        "4D hypercomplex Mandelbrot set q -> q^2 + c, c = (point, slice); runs its own orbit from the point.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{
            "slice", ParamType::Float, {0.0, 0.0, 0.0}, -2.0, 2.0, "c's fourth coordinate: which 3D slice is seen."},
        ParamDecl{"orbit", ParamType::Float, {12.0, 0.0, 0.0}, 1.0, 1000.0, "Iterations of the hypercomplex orbit."},
        ParamDecl{"escape",
                  ParamType::Float,
                  {10.0, 0.0, 0.0},
                  2.0,
                  1000.0,
                  "Escape radius of the orbit (larger: a tighter estimate)."},
    };

    static constexpr std::string_view glsl = R"(
    vec4 k = vec4(p.xyz, slice), q = k;
    float dq = abs(p.w), q2 = dot(q, q);
    int i = 0;
    for (; i < int(orbit) && q2 < escape * escape; ++i) {
        dq = 2.0 * sqrt(q2) * dq + abs(p.w);
        q = vec4(q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w, 2.0 * (q.x * q.y - q.w * q.z),
                 2.0 * (q.x * q.z - q.y * q.w), 2.0 * (q.x * q.w - q.y * q.z)) + k;
        q2 = dot(q, q);
    }
    float r = sqrt(q2);
    return q2 < escape * escape ? 0.0 : 0.5 * (log(r) - exp2(float(i - int(orbit))) * log(escape)) * r / dq;
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        return mandelbrotOrbitEstimate(p, a.f(0), a.f(1), a.f(2), hypercomplexSquare);
    }
};

// The Julia form (Mandelbulber2's hypercomplex with julia_mode): q -> q^2 + k from q = (point,
// slice), k fixed; the running derivative |dq| -> 2 |q| |dq| (no dc/dp: k does not move with the
// point), and the estimate of K_n's surface as above.
struct HypercomplexJulia {
    static constexpr std::string_view id = "hypercomplex_julia";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Hypercomplex Julia";
    static constexpr std::string_view help =
        "4D hypercomplex Julia set q -> q^2 + k from q = (point, slice); runs its own orbit from the point.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"constant", ParamType::Vec3, {-0.5, 0.0, 0.0}, -4.0, 4.0, "k's first three coordinates."},
        ParamDecl{"constant_w", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "k's fourth coordinate."},
        ParamDecl{"slice",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -2.0,
                  2.0,
                  "The start's fourth coordinate: which slice is seen."},
        ParamDecl{"orbit", ParamType::Float, {12.0, 0.0, 0.0}, 1.0, 1000.0, "Iterations of the hypercomplex orbit."},
        ParamDecl{"escape",
                  ParamType::Float,
                  {10.0, 0.0, 0.0},
                  2.0,
                  1000.0,
                  "Escape radius of the orbit (larger: a tighter estimate)."},
    };

    static constexpr std::string_view glsl = R"(
    vec4 q = vec4(p.xyz, slice);
    float dq = abs(p.w), q2 = dot(q, q);
    int i = 0;
    for (; i < int(orbit) && q2 < escape * escape; ++i) {
        dq *= 2.0 * sqrt(q2);
        q = vec4(q.x * q.x - q.y * q.y - q.z * q.z - q.w * q.w, 2.0 * (q.x * q.y - q.w * q.z),
                 2.0 * (q.x * q.z - q.y * q.w), 2.0 * (q.x * q.w - q.y * q.z)) + vec4(constant, constant_w);
        q2 = dot(q, q);
    }
    float r = sqrt(q2);
    return q2 < escape * escape ? 0.0 : 0.5 * (log(r) - exp2(float(i - int(orbit))) * log(escape)) * r / dq;
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        return juliaOrbitEstimate(p, vec4(a.v3(0), a.f(1)), a.f(2), a.f(3), a.f(4), hypercomplexSquare);
    }
};

}  // namespace fraktal::blocks
