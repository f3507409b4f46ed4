#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Graeme McLaren's parabolic sphere fold (Mandelbulber2's transf_spherical_fold_parab,
// TransfSphericalFoldParabIteration in fractal_formulas.cpp of 2.20). With rr = |p|^2 + r2_offset
// taken before anything moves, the point is shifted by `offset`, scaled by `scale` and multiplied
// by m(rr): max_scale - rr^2 f below half of max_r2, 1 + (max_r2 - rr)^2 f up to max_r2 and 1
// beyond, f = (max_scale - 1) / 2 / (max_r2 / 2)^2, so m falls from max_scale at the centre to 1 at
// max_r2 along two parabolas that meet at half of it. Mandelbulber2 takes the shift back only in
// the outer band: the block does the same, so with an offset the map jumps at half of max_r2.
//
// Its stretch at the point is at most |scale| (|m| + 2 |m'(rr)| |p + offset| |p|) (the radial
// derivative of p m(|p|^2) and the turn-free tangential one, m). With `mb2_derivative` the running
// derivative is Mandelbulber2's, (w |scale| + 1) m, which leaves the radial part out (at half of
// max_r2 it is (max_scale + 1) / 2 against 2 (max_scale - 1) radially): the import asks for it, the
// estimate is then no bound, and the step factor is measured.
struct SphereFoldParabolic {
    static constexpr std::string_view id = "sphere_fold_parabolic";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Parabolic sphere fold";
    static constexpr std::string_view help =
        "Scales the point by m(|p|^2): max_scale at the centre falling to 1 at max_r2 along two parabolas "
        "(Mandelbulber2's transf_spherical_fold_parab).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::string_view jump =
        "with an offset its map jumps at half of max_r2 (Mandelbulber2 takes the offset back in the outer band "
        "only), and with mb2_derivative its running derivative leaves out the radial stretch";
    static DerivativeBound derivativeFor(Args a) {
        const vec3 offset = a.v3(4);
        return a.f(5) > 0.5 || offset != vec3(0.0) ? DerivativeBound::None : DerivativeBound::Local;
    }
    static constexpr std::array params{
        ParamDecl{"max_scale", ParamType::Float, {4.0, 0.0, 0.0}, 0.0, 10.0, "m at the centre."},
        ParamDecl{"max_r2", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "The squared radius where m reaches 1."},
        ParamDecl{"r2_offset", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Added to |p|^2 before m is taken."},
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the shifted point before m."},
        ParamDecl{"offset",
                  ParamType::Vec3,
                  {0.0, 0.0, 0.0},
                  -10.0,
                  10.0,
                  "Added before the fold, taken back in the outer band only (as Mandelbulber2)."},
        toggleParam("mb2_derivative", false,
                    "On: the running derivative is Mandelbulber2's, (w |scale| + 1) m (no bound; the step factor is "
                    "measured)."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float rr = dot(v, v) + r2_offset;
    vec3 shifted = v + offset;
    float halfMax = 0.5 * max_r2;
    float f = 0.5 * (max_scale - 1.0) / (halfMax * halfMax);
    float m = 1.0, dm = 0.0;
    bool outer = false;
    if (rr < halfMax) {
        m = max_scale - rr * rr * f;
        dm = -2.0 * rr * f;
    } else if (rr < max_r2) {
        m = 1.0 + (max_r2 - rr) * (max_r2 - rr) * f;
        dm = -2.0 * (max_r2 - rr) * f;
        outer = true;
    }
    p.xyz = shifted * scale * m - (outer ? offset : vec3(0.0));
    pointW *= scale * m;
    if (mb2_derivative > 0.5)
        p.w = (p.w * abs(scale) + 1.0) * m;
    else
        p.w *= abs(scale) * (abs(m) + 2.0 * abs(dm) * length(shifted) * length(v));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double maxScale = a.f(0), maxR2 = a.f(1), r2Offset = a.f(2), scale = a.f(3);
        const vec3 offset = a.v3(4);
        const vec3 v = p.xyz;
        const double rr = dot(v, v) + r2Offset;
        const vec3 shifted = v + offset;
        const double halfMax = 0.5 * maxR2;
        const double f = 0.5 * (maxScale - 1.0) / (halfMax * halfMax);
        double m = 1.0, dm = 0.0;
        bool outer = false;
        if (rr < halfMax) {
            m = maxScale - rr * rr * f;
            dm = -2.0 * rr * f;
        } else if (rr < maxR2) {
            m = 1.0 + (maxR2 - rr) * (maxR2 - rr) * f;
            dm = -2.0 * (maxR2 - rr) * f;
            outer = true;
        }
        p.xyz = shifted * scale * m - (outer ? offset : vec3(0.0));
        p.pointW *= scale * m;
        if (a.f(5) > 0.5)
            p.w = (p.w * std::abs(scale) + 1.0) * m;
        else
            p.w *= std::abs(scale) * (std::abs(m) + 2.0 * std::abs(dm) * length(shifted) * length(v));
    }
};

}  // namespace fraktal::blocks
