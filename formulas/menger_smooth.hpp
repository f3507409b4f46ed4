#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's smooth Menger sponge (fractal_formulas.cpp MengerSmoothIteration and
// MengerSmoothMod1Iteration, after knighty's smooth folds): the sponge's abs, sort and z fold with
// each corner rounded. |x| is sqrt(x^2 + k_abs) + a (the mod 1's offset abs); each pair is sorted by t = w (d -
// sqrt(d^2 + k)) with d their difference (x - t, y + t: w = 1/2 is the smooth max and min); z is folded about the
// centre o.z (s - 1) / s by -sqrt((z - centre)^2 + k_fold); then scaled by s about the corner (o.x (s - 1), o.y (s -
// 1)). Each rounded abs has slope at most 1, each sort's Jacobian
// [[1 - t', t'], [t', 1 - t']] (t' in [0, 2w]) stretches by at most max(1, |1 - 4w|), the offset
// a none, so the running derivative grows by s max(1, |1 - 4w|)^3, a bound everywhere.
struct MengerSmooth {
    static constexpr std::string_view id = "menger_smooth";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Smooth Menger";
    static constexpr std::string_view help =
        "The Menger sponge's abs, sort and z fold with rounded corners, then the scale about its corner.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {3.0, 0.0, 0.0}, 1.01, 5.0, "Scale s of each step."},
        ParamDecl{"offset", ParamType::Vec3, {1.0, 1.0, 0.5}, -4.0, 4.0, "The corner o scaled about."},
        ParamDecl{"abs_smoothness", ParamType::Float, {0.005, 0.0, 0.0}, 0.0, 1.0, "Rounding of the abs fold."},
        ParamDecl{
            "abs_offset", ParamType::Float, {0.0, 0.0, 0.0}, -2.0, 2.0, "a added to each coordinate after the abs."},
        ParamDecl{"sort_smoothness",
                  ParamType::Vec3,
                  {0.005, 0.005, 0.005},
                  0.0,
                  1.0,
                  "Rounding of the x-y, x-z and y-z sorts."},
        ParamDecl{"fold_smoothness", ParamType::Float, {0.005, 0.0, 0.0}, 0.0, 1.0, "Rounding of z's fold."},
        ParamDecl{"sort_weight", ParamType::Float, {0.5, 0.0, 0.0}, 0.0, 1.0, "w: 1/2 sorts, less blends."},
    };

    static constexpr std::string_view glsl = R"(
    float s = scale, w = sort_weight;
    vec3 v = sqrt(p.xyz * p.xyz + abs_smoothness) + abs_offset;
    float t = v.x - v.y;
    t = w * (t - sqrt(t * t + sort_smoothness.x));
    v.x -= t;
    v.y += t;
    t = v.x - v.z;
    t = w * (t - sqrt(t * t + sort_smoothness.y));
    v.x -= t;
    v.z += t;
    t = v.y - v.z;
    t = w * (t - sqrt(t * t + sort_smoothness.z));
    v.y -= t;
    v.z += t;
    float centre = offset.z * (s - 1.0) / s;
    v.z = centre - sqrt((v.z - centre) * (v.z - centre) + fold_smoothness);
    p.xyz = vec3(s * v.x - offset.x * (s - 1.0), s * v.y - offset.y * (s - 1.0), s * v.z);
    float sortStretch = max(1.0, abs(1.0 - 4.0 * w));
    p.w *= s * sortStretch * sortStretch * sortStretch;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), abs_smoothness = a.f(2), abs_offset = a.f(3), fold_smoothness = a.f(5),
                     sort_weight = a.f(6);
        const vec3 offset = a.v3(1), sort_smoothness = a.v3(4);
        double s = scale, w = sort_weight;
        vec3 v = glm::sqrt(p.xyz * p.xyz + abs_smoothness) + abs_offset;
        double t = v.x - v.y;
        t = w * (t - std::sqrt(t * t + sort_smoothness.x));
        v.x -= t;
        v.y += t;
        t = v.x - v.z;
        t = w * (t - std::sqrt(t * t + sort_smoothness.y));
        v.x -= t;
        v.z += t;
        t = v.y - v.z;
        t = w * (t - std::sqrt(t * t + sort_smoothness.z));
        v.y -= t;
        v.z += t;
        double centre = offset.z * (s - 1.0) / s;
        v.z = centre - std::sqrt((v.z - centre) * (v.z - centre) + fold_smoothness);
        p.xyz = vec3(s * v.x - offset.x * (s - 1.0), s * v.y - offset.y * (s - 1.0), s * v.z);
        double sortStretch = max(1.0, abs(1.0 - 4.0 * w));
        p.w *= s * sortStretch * sortStretch * sortStretch;
    }
};

}  // namespace fraktal::blocks
