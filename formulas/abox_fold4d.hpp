#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The folds of Mandelbulber2's abox4d, the Mandelbox in four dimensions (2.20's Abox4dIteration in
// fractal_formulas.cpp), on the 4D point (xyz, P4::pointW; formulas/four_d.hpp): w first moves by
// Mandelbulber2's Cpara parabola of the iteration i (offset + slope i + 0.001 scale i^2), then
// Tglad's fold of each coordinate at its limit (|x + l| - |x - l| - x), then the sphere fold
// measured on q = (|v|^2)^power: v' = (v + o) k - o with k = max_r2 / min_r2 inside q < min_r2,
// max_r2 / q below max_r2, else 1 (the radii from the origin, the scaling about -o; an inner
// radius above the fixed one is taken as the fixed one, as `sphere_fold` does, so that the map stays
// continuous). The scale,
// the turn and the added constant that follow in Mandelbulber2 are `scale`, `rotate4d` and
// `translate` (each carries w).
//
// The running derivative: Tglad's fold is a reflection and a shift at a limit above 0, and
// stretches by 3 between -|l| and |l| at a limit below 0 (its slope there is -3). In the sphere
// fold's shell k = max_r2 |v|^(-2 power) varies, and the Jacobian is k (I - 2 power a b^T) with
// b = v / |v| and a = (v + o) / |v|; its largest singular value is k times the root of l^2 - T l +
// D with T = 2 - 4 power a.b + 4 power^2 |a|^2 and D = (1 - 2 power a.b)^2 (at power 1 and o = 0
// a reflection, k alone). Mandelbulber2 carries k alone.
struct AboxFold4d {
    static constexpr std::string_view id = "abox_fold4d";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbox folds 4D";
    static constexpr std::string_view help =
        "The Mandelbox's folds in 4D (Mandelbulber2's abox4d): w moved by a parabola of the iteration, Tglad's fold of "
        "x, y, z and w at their limits, then the sphere fold of squared radii min_r2 and max_r2 measured on "
        "|v|^(2 power), scaling about -offset.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "Fold limit per axis (x, y, z)."},
        ParamDecl{"limit_w", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "The fold limit of w."},
        ParamDecl{"min_r2", ParamType::Float, {0.25, 0.0, 0.0}, 1e-4, 4.0, "Squared inner radius."},
        ParamDecl{"max_r2", ParamType::Float, {1.0, 0.0, 0.0}, 1e-4, 4.0, "Squared fixed radius."},
        ParamDecl{"power",
                  ParamType::Float,
                  {1.0, 0.0, 0.0},
                  0.1,
                  4.0,
                  "The sphere fold measures |v|^2 raised to this power (Mandelbulber2's rPower)."},
        ParamDecl{"offset", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "The sphere fold scales about -offset."},
        ParamDecl{"offset_w", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "The offset's fourth coordinate."},
        ParamDecl{"w_parabola",
                  ParamType::Vec3,
                  {0.0, 0.0, 0.0},
                  -10.0,
                  10.0,
                  "Added to w first at iteration i: x + y i + 0.001 z i^2 (Mandelbulber2's Cpara offset, slope and "
                  "scale)."},
    };

    static constexpr std::string_view glsl = R"(
    float i = float(iteration);
    vec4 v = vec4(p.xyz, pointW + w_parabola.x + w_parabola.y * i + 0.001 * w_parabola.z * i * i);
    vec4 l = vec4(limit, limit_w);
    v = abs(v + l) - abs(v - l) - v;
    float rr = dot(v, v);
    float q = pow(rr, power);
    vec4 o = vec4(offset, offset_w);
    float inner = min(min_r2, max_r2);
    float k = q < inner ? max_r2 / inner : q < max_r2 ? max_r2 / q : 1.0;
    float stretch = k;
    if (q >= inner && q < max_r2) {
        float ab = 1.0 + dot(o, v) / rr, aa = dot(v + o, v + o) / rr;
        float t = 2.0 - 4.0 * power * ab + 4.0 * power * power * aa;
        float d = (1.0 - 2.0 * power * ab) * (1.0 - 2.0 * power * ab);
        stretch = k * sqrt(0.5 * (t + sqrt(max(t * t - 4.0 * d, 0.0))));
    }
    v = (v + o) * k - o;
    p.xyz = v.xyz;
    pointW = v.w;
    p.w *= (any(lessThan(l, vec4(0.0))) ? 3.0 : 1.0) * stretch;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 limit = a.v3(0), offset = a.v3(5), parabola = a.v3(7);
        const double limit_w = a.f(1), min_r2 = a.f(2), max_r2 = a.f(3), power = a.f(4), offset_w = a.f(6);
        const double i = double(p.iteration);
        vec4 v(p.xyz, p.pointW + parabola.x + parabola.y * i + 0.001 * parabola.z * i * i);
        const vec4 l(limit, limit_w);
        v = glm::abs(v + l) - glm::abs(v - l) - v;
        const double rr = dot(v, v);
        const double q = std::pow(rr, power);
        const vec4 o(offset, offset_w);
        const double inner = std::min(min_r2, max_r2);
        const double k = q < inner ? max_r2 / inner : q < max_r2 ? max_r2 / q : 1.0;
        double stretch = k;
        if (q >= inner && q < max_r2) {
            const double ab = 1.0 + dot(o, v) / rr, aa = dot(v + o, v + o) / rr;
            const double t = 2.0 - 4.0 * power * ab + 4.0 * power * power * aa;
            const double d = (1.0 - 2.0 * power * ab) * (1.0 - 2.0 * power * ab);
            stretch = k * std::sqrt(0.5 * (t + std::sqrt(std::max(t * t - 4.0 * d, 0.0))));
        }
        v = (v + o) * k - o;
        p.xyz = vec3(v);
        p.pointW = v.w;
        p.w *= (glm::any(glm::lessThan(l, vec4(0.0))) ? 3.0 : 1.0) * stretch;
    }
};

}  // namespace fraktal::blocks
