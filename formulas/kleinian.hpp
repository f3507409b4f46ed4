#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Jos Leys' Kleinian group limit set (Fragmentarium "Kleinian", after Knighty): wrap x (sheared
// by b/a y) and z into the box, rotate half a turn about (-b/2, a/2) above the separation line,
// then apply the Mobius generator: invert in the unit sphere, v -> (-b - x, a + y, z) after
// v -> -v / |v|^2. Wraps and the half turn keep distances; the inversion scales them by
// 1 / |v|^2, and so does the running derivative.
struct Kleinian {
    static constexpr std::string_view id = "kleinian";
    static constexpr std::string_view label = "Kleinian (Jos Leys)";
    static constexpr std::string_view help =
        "Jos Leys' Kleinian limit set step: wrap, half turn above the separation line, Mobius inversion.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where it wraps x and z into its box and where it turns half above the separation line";
    static constexpr std::array params{
        ParamDecl{"klein_r",
                  ParamType::Float,
                  {1.94, 0.0, 0.0},
                  1.5,
                  2.1,
                  "Shapes the circles of the set: near 2 they pack tightly (the real part a of the generator's "
                  "trace)."}
            .labelled("Packing"),
        ParamDecl{"klein_i",
                  ParamType::Float,
                  {0.03, 0.0, 0.0},
                  -0.5,
                  0.5,
                  "Leans the set sideways; 0 keeps it symmetric (the imaginary part b of the generator's trace)."}
            .labelled("Lean"),
        ParamDecl{"box_size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.1, 4.0, "Wrap half-widths in x and z (y unused)."},
        ParamDecl{
            "separation", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 1.0, "Bend of the separation line (0: straight)."},
    };

    static constexpr std::string_view glsl = R"(
    float a = klein_r, b = klein_i;
    p.x += b / a * p.y;
    p.xz = p.xz + box_size.xz - 2.0 * box_size.xz * floor((p.xz + box_size.xz) / (2.0 * box_size.xz)) - box_size.xz;
    p.x -= b / a * p.y;
    float u = p.x + b * 0.5;
    if (p.y >= a * 0.5 + separation * (2.0 * a - 1.95) / 4.0 * sign(u) * (1.0 - exp(-(7.2 - (1.95 - a) * 15.0) * abs(u))))
        p.xyz = vec3(-b, a, 0.0) - p.xyz;
    float ir = 1.0 / max(dot(p.xyz, p.xyz), 1e-12);
    p.xyz *= -ir;
    p.x = -b - p.x;
    p.y = a + p.y;
    p.w *= ir;
)";
    static void apply(P4& p, const vec3&, Args args) {
        const double klein_r = args.f(0), klein_i = args.f(1), separation = args.f(3);
        const vec3 box_size = args.v3(2);
        double a = klein_r, b = klein_i;
        p.xyz.x += b / a * p.xyz.y;
        p.xyz.x = p.xyz.x + box_size.x - 2.0 * box_size.x * std::floor((p.xyz.x + box_size.x) / (2.0 * box_size.x)) -
                  box_size.x;
        p.xyz.z = p.xyz.z + box_size.z - 2.0 * box_size.z * std::floor((p.xyz.z + box_size.z) / (2.0 * box_size.z)) -
                  box_size.z;
        p.xyz.x -= b / a * p.xyz.y;
        double u = p.xyz.x + b * 0.5;
        if (p.xyz.y >= a * 0.5 + separation * (2.0 * a - 1.95) / 4.0 * glm::sign(u) *
                                     (1.0 - std::exp(-(7.2 - (1.95 - a) * 15.0) * abs(u))))
            p.xyz = vec3(-b, a, 0.0) - p.xyz;
        double ir = 1.0 / std::max(dot(p.xyz, p.xyz), 1e-12);
        p.xyz *= -ir;
        p.xyz.x = -b - p.xyz.x;
        p.xyz.y = a + p.xyz.y;
        p.w *= ir;
    }
};

// Jos Leys' Kleinian in Mandelbulber2's form (fractal_formulas.cpp JosKleinianIteration; Jos Leys,
// fractalforums.com "an escape-time algorithm for Kleinian group limit sets"): the point wrapped
// into the box [-s.x, s.x) x [1 - s.y, 1 - s.y + a s.y) x [-s.z, s.z) (common_math.cpp wrap; no
// shear, y wrapped too), turned half about (-b/2, a/2) above the wavy separation line
// y = a (0.5 + 0.2 sin(sign(b) pi (x + b/2) / s.x)), then the Mobius generator as in `kleinian`.
// Close it with kleinian_de (Mandelbulber2's Jos-Kleinian DE function).
struct JosKleinian {
    static constexpr std::string_view id = "jos_kleinian";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Kleinian (Mandelbulber2)";
    static constexpr std::string_view help =
        "Jos Leys' Kleinian step as Mandelbulber2 has it: wrap x, y and z, half turn above a wavy line, Mobius "
        "inversion.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where it wraps the point into its box and where it turns half above the separation line";
    static constexpr std::array params{
        ParamDecl{"klein_r",
                  ParamType::Float,
                  {2.0, 0.0, 0.0},
                  1.5,
                  2.1,
                  "Shapes the circles of the set: near 2 they pack tightly (the real part a of the generator's "
                  "trace)."}
            .labelled("Packing"),
        ParamDecl{"klein_i",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -0.5,
                  0.5,
                  "Leans the set sideways; 0 keeps it symmetric (the imaginary part b of the generator's trace)."}
            .labelled("Lean"),
        ParamDecl{"box_size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.1, 4.0, "Wrap sizes s (y's period is a s.y)."},
    };

    static constexpr std::string_view glsl = R"(
    float a = klein_r, b = klein_i;
    vec3 period = vec3(2.0 * box_size.x, a * box_size.y, 2.0 * box_size.z);
    vec3 start = vec3(-box_size.x, 1.0 - box_size.y, -box_size.z);
    vec3 v = p.xyz - start;
    v = v - period * floor(v / period) + start;
    if (v.y >= a * (0.5 + 0.2 * sin(sign(b) * 3.14159265358979 * (v.x + b * 0.5) / box_size.x)))
        v = vec3(-b, a, 0.0) - v;
    float ir = 1.0 / max(dot(v, v), 1e-12);
    v *= -ir;
    p.xyz = vec3(-b - v.x, a + v.y, v.z);
    p.w *= ir;
)";
    static void apply(P4& p, const vec3&, Args args) {
        const double klein_r = args.f(0), klein_i = args.f(1);
        const vec3 box_size = args.v3(2);
        double a = klein_r, b = klein_i;
        vec3 period = vec3(2.0 * box_size.x, a * box_size.y, 2.0 * box_size.z);
        vec3 start = vec3(-box_size.x, 1.0 - box_size.y, -box_size.z);
        vec3 v = p.xyz - start;
        v = v - period * glm::floor(v / period) + start;
        if (v.y >= a * (0.5 + 0.2 * std::sin(glm::sign(b) * 3.14159265358979 * (v.x + b * 0.5) / box_size.x)))
            v = vec3(-b, a, 0.0) - v;
        double ir = 1.0 / std::max(dot(v, v), 1e-12);
        v *= -ir;
        p.xyz = vec3(-b - v.x, a + v.y, v.z);
        p.w *= ir;
    }
};

// Jos Leys' Kleinian distance (the closing line of Fragmentarium's Jos Leys / Knighty Kleinian
// example: DE = min(y, Clamp_y) / max(DF, Clamp_DF), y = min(z.y, a - z.y)): after the loop the
// orbit has been mapped into the strip 0 <= y <= a between the two tangent planes, whose
// half-spaces y < 0 and y > a the group maps onto the balls of the picture. min(y, a - y) is the
// distance to those half-spaces, capped at clamp_y (the half turn is applied on one side of the
// separation line only, so a neighbour across it can follow another orbit into a ball: far from
// both planes the end point says little) and divided by the running derivative, at least
// clamp_df. Negative inside the balls, so the set has an inside. The cap makes the estimate
// small in open space; `fraktal check` measures the factor that keeps it under the distance.
struct KleinianEstimator {
    static constexpr std::string_view id = "kleinian_de";
    static constexpr std::string_view label = "Kleinian distance";
    static constexpr std::string_view help =
        "Jos Leys' Kleinian estimate: distance to the strip's planes y = 0 and y = a, over the running derivative.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"klein_r", ParamType::Float, {1.94, 0.0, 0.0}, 1.5, 2.1, "Strip height: the Kleinian step's Packing."}
            .labelled("Packing"),
        ParamDecl{"clamp_y", ParamType::Float, {0.3, 0.0, 0.0}, 0.01, 2.0, "Caps the distance to the planes."}.labelled(
            "Plane distance cap"),
        ParamDecl{"clamp_df",
                  ParamType::Float,
                  {2.0, 0.0, 0.0},
                  0.1,
                  8.0,
                  "The least the distance is divided by: larger makes the rays step more carefully."}
            .labelled("Step caution"),
    };

    static constexpr std::string_view glsl = R"(
    float y = min(p.y, klein_r - p.y);
    return min(y, clamp_y) / max(abs(p.w), clamp_df);
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double klein_r = a.f(0), clamp_y = a.f(1), clamp_df = a.f(2);
        double y = std::min(p.xyz.y, klein_r - p.xyz.y);
        return std::min(y, clamp_y) / std::max(abs(p.w), clamp_df);
    }
};

}  // namespace fraktal::blocks
