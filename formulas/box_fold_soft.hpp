#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Tglad's box fold per axis (|x + L| - |x - L| - x) followed by Mandelbulber2's parabolic
// softening (the pseudo-Kleinian mod 2's F fold with its A option, fractal_formulas.cpp
// PseudoKleinianMod2Iteration): each folded coordinate moves towards 0 by s x^2 / 2L within L of
// the plane and by s (2L - |x|)^2 / 2L between L and 2L, which rounds the fold's crease at L. The
// map is continuous, with slope between 1 - s and 1 + s, so the running derivative grows by
// 1 + max |s| (at most 1 where s is 0: the plain fold), a bound everywhere.
struct BoxFoldSoft {
    static constexpr std::string_view id = "box_fold_soft";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Soft box fold";
    static constexpr std::string_view help =
        "Box fold per axis at limits L, each coordinate then eased towards 0 by s x^2 / 2L (a parabolic "
        "softening).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 4.0, "Folding limits L for x, y and z."},
        ParamDecl{"softness", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "s per axis (0: the plain fold)."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = abs(p.xyz + limit) - abs(p.xyz - limit) - p.xyz;
    for (int i = 0; i < 3; ++i) {
        float a = abs(v[i]), l = limit[i], ease = 0.0;
        if (a < l) ease = a * a / (2.0 * l);
        if (a > l && a < 2.0 * l) ease = (2.0 * l - a) * (2.0 * l - a) / (2.0 * l);
        v[i] -= sign(v[i]) * ease * softness[i];
    }
    p.xyz = v;
    p.w *= 1.0 + max(abs(softness.x), max(abs(softness.y), abs(softness.z)));
)";
    static void apply(P4& p, const vec3&, Args args) {
        const vec3 limit = args.v3(0), softness = args.v3(1);
        vec3 v = abs(p.xyz + limit) - abs(p.xyz - limit) - p.xyz;
        for (int i = 0; i < 3; ++i) {
            double a = abs(v[i]), l = limit[i], ease = 0.0;
            if (a < l) ease = a * a / (2.0 * l);
            if (a > l && a < 2.0 * l) ease = (2.0 * l - a) * (2.0 * l - a) / (2.0 * l);
            v[i] -= glm::sign(v[i]) * ease * softness[i];
        }
        p.xyz = v;
        p.w *= 1.0 + max(abs(softness.x), max(abs(softness.y), abs(softness.z)));
    }
};

// Tglad's box fold with its two limits and its mirror apart (the pseudo-Kleinian std DE's F fold,
// fractal_formulas.cpp PseudoKleinianStdDEIteration): x -> |x + low| - |x - high| - m x, then
// `offset` added. low = high = L and m = 1 is the box fold at L. Its slope on each axis is -m or
// 2 - m (and -2 - m where high < -low), continuous, so the running derivative grows by the
// largest of those magnitudes over the axes, a bound everywhere.
struct BoxFoldGeneral {
    static constexpr std::string_view id = "box_fold_general";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "General box fold";
    static constexpr std::string_view help =
        "x -> |x + low| - |x - high| - m x per axis, plus offset: the box fold with its limits and mirror apart.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"low", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "Limit below: |x + low|."},
        ParamDecl{"high", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "Limit above: |x - high|."},
        ParamDecl{"mirror", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "m: the multiple of x taken off."},
        ParamDecl{"offset", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Added after the fold."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz = abs(p.xyz + low) - abs(p.xyz - high) - p.xyz * mirror + offset;
    vec3 slope = max(abs(mirror), abs(2.0 - mirror));
    slope = mix(slope, max(slope, abs(2.0 + mirror)), lessThan(high, -low));
    p.w *= max(slope.x, max(slope.y, slope.z));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 low = a.v3(0), high = a.v3(1), mirror = a.v3(2), offset = a.v3(3);
        p.xyz = abs(p.xyz + low) - abs(p.xyz - high) - p.xyz * mirror + offset;
        vec3 slope = max(abs(mirror), abs(2.0 - mirror));
        slope = glm::mix(slope, max(slope, abs(2.0 + mirror)), glm::lessThan(high, -low));
        p.w *= max(slope.x, max(slope.y, slope.z));
    }
};

}  // namespace fraktal::blocks
