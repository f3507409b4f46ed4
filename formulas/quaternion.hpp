#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Quaternion fractals: the orbit of q -> q^2 + k in four dimensions, seen through a 3D slice
// (the fourth coordinate of the start fixed at `slice`). The iteration state p carries three
// coordinates and the running scale, so a 4D orbit does not fit in it: these are estimators that
// run their own orbit from the point the node list leaves (folds, rotations and scales before them
// shape space; the running scale p.w divides the estimate as for every estimator).
// Quaternion square, real part first: (a, v)^2 = (a^2 - |v|^2, 2 a v) (Hart, Sandin, Kauffman,
// "Ray tracing deterministic 3-D fractals", 1989). Its derivative bound |dq| -> 2 |q| |dq| and
// the estimate 0.5 |q| log|q| / |dq| are theirs; the Mandelbrot form adds dc/dp (the running
// scale) each step, as add_c does. An orbit that stays within the bailout is inside (0).
// The object drawn is the orbit's truncation, K_n = {q: |q_n| <= escape after n = orbit steps},
// which is larger than the limit set that 0.5 |q| log|q| / |dq| measures to, so that estimate
// overshoots near its surface (2.3x, measured by `fraktal check`). With the potential
// G = log|q_i| / 2^i of an orbit that escaped at step i, K_n's surface is the level
// G = log(escape) / 2^n; the distance to it is estimated as (G - that level) / |grad G|, which is
// 0.5 |q| (log|q| - 2^(i - n) log(escape)) / |dq| with Hart's factor 0.5.

// The Mandelbrot form's own orbit, q -> square(q) + k from q = k = (point, slice), and the
// estimate of K_n's surface above (dq -> 2 |q| dq + |p.w|, as add_c adds dc/dp each step): the CPU
// side of the 4D Mandelbrot sets (quaternion here, hypercomplex.hpp), each with its square.
template <class Square>
double mandelbrotOrbitEstimate(const P4& p, double slice, double orbit, double escape, Square square) {
    const vec4 k = vec4(p.xyz, slice);
    vec4 q = k;
    double dq = abs(p.w), q2 = dot(q, q);
    int i = 0;
    for (; i < int(orbit) && q2 < escape * escape; ++i) {
        dq = 2.0 * std::sqrt(q2) * dq + abs(p.w);
        q = square(q) + k;
        q2 = dot(q, q);
    }
    const double r = std::sqrt(q2);
    return q2 < escape * escape ? 0.0 : 0.5 * (std::log(r) - std::exp2(i - int(orbit)) * std::log(escape)) * r / dq;
}

// The Julia form's own orbit, q -> square(q) + k from q = (point, slice), with dq -> 2 |q| dq (k
// does not move with the point) and the estimate of K_n's surface as above: the CPU side of the
// 4D Julia sets (quaternion here, hypercomplex.hpp).
template <class Square>
double juliaOrbitEstimate(const P4& p, const vec4& k, double slice, double orbit, double escape, Square square) {
    vec4 q = vec4(p.xyz, slice);
    double dq = abs(p.w), q2 = dot(q, q);
    int i = 0;
    for (; i < int(orbit) && q2 < escape * escape; ++i) {
        dq *= 2.0 * std::sqrt(q2);
        q = square(q) + k;
        q2 = dot(q, q);
    }
    const double r = std::sqrt(q2);
    return q2 < escape * escape ? 0.0 : 0.5 * (std::log(r) - std::exp2(i - int(orbit)) * std::log(escape)) * r / dq;
}

struct QuaternionJulia {
    static constexpr std::string_view id = "quaternion_julia";
    static constexpr std::string_view label = "Quaternion Julia";
    static constexpr std::string_view help =
        "4D Julia set q -> q^2 + k, sliced at w = slice; runs its own orbit from the point.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"constant",
                  ParamType::Vec3,
                  {-0.2, 0.6, 0.2},
                  -2.0,
                  2.0,
                  "k: real part and the first two imaginary parts."},
        ParamDecl{"constant_w", ParamType::Float, {0.0, 0.0, 0.0}, -2.0, 2.0, "k: the third imaginary part."},
        ParamDecl{"slice",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -2.0,
                  2.0,
                  "The start's fourth coordinate: which 3D slice is seen."},
        ParamDecl{"orbit", ParamType::Float, {12.0, 0.0, 0.0}, 1.0, 64.0, "Iterations of the quaternion orbit."},
        ParamDecl{"escape",
                  ParamType::Float,
                  {16.0, 0.0, 0.0},
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
        q = vec4(q.x * q.x - dot(q.yzw, q.yzw), 2.0 * q.x * q.yzw) + vec4(constant, constant_w);
        q2 = dot(q, q);
    }
    float r = sqrt(q2);
    return q2 < escape * escape ? 0.0 : 0.5 * (log(r) - exp2(float(i - int(orbit))) * log(escape)) * r / dq;
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        return juliaOrbitEstimate(p, vec4(a.v3(0), a.f(1)), a.f(2), a.f(3), a.f(4), [](const vec4& q) {
            return vec4(q.x * q.x - dot(vec3(q.y, q.z, q.w), vec3(q.y, q.z, q.w)), 2.0 * q.x * vec3(q.y, q.z, q.w));
        });
    }
};

struct QuaternionMandelbrot {
    static constexpr std::string_view id = "quaternion_mandelbrot";
    static constexpr std::string_view label = "Quaternion Mandelbrot";
    static constexpr std::string_view help =
        "4D Mandelbrot set q -> q^2 + c, c = (point, slice); runs its own orbit from the point.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{
            "slice", ParamType::Float, {0.0, 0.0, 0.0}, -2.0, 2.0, "c's fourth coordinate: which 3D slice is seen."},
        ParamDecl{"orbit", ParamType::Float, {12.0, 0.0, 0.0}, 1.0, 64.0, "Iterations of the quaternion orbit."},
        ParamDecl{"escape",
                  ParamType::Float,
                  {16.0, 0.0, 0.0},
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
        q = vec4(q.x * q.x - dot(q.yzw, q.yzw), 2.0 * q.x * q.yzw) + k;
        q2 = dot(q, q);
    }
    float r = sqrt(q2);
    return q2 < escape * escape ? 0.0 : 0.5 * (log(r) - exp2(float(i - int(orbit))) * log(escape)) * r / dq;
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        return mandelbrotOrbitEstimate(p, a.f(0), a.f(1), a.f(2), [](const vec4& q) {
            return vec4(q.x * q.x - dot(vec3(q.y, q.z, q.w), vec3(q.y, q.z, q.w)), 2.0 * q.x * vec3(q.y, q.z, q.w));
        });
    }
};

}  // namespace fraktal::blocks
