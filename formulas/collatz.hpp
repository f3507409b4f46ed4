#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The Collatz map in 3D (Mandelbulber2's collatz and collatz_mod; mathr.co.uk "Collatz fractal",
// 2016): (b + s4 v - (a + s2 v) * R(v)) s (products per axis), R the turn of v by angle pi about
// the axis a as Mandelbulber2's RotateAroundVectorByAngle writes it, with a not normalised
// (v cos t + (a x v) sin t + a (a . v)(1 - cos t)). The defaults are the Collatz map (1 + 4 v -
// (1 + 2 v) * R(v)) / 4. The running derivative is a bound on the Jacobian's norm (|s| times s4,
// plus s2 |R v| and |a + s2 v| |R|, |R| at most |cos t| + |a| |sin t| + |a|^2 |1 - cos t|), or with
// mb2_derivative Mandelbulber2's 4.
struct Collatz {
    static constexpr std::string_view id = "collatz";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Collatz";
    static constexpr std::string_view help =
        "The Collatz map in 3D: (b + s4 v - (a + s2 v) * R(v)) s, R a turn about a.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::string_view jump =
        "with mb2_derivative its running derivative is Mandelbulber2's constant 4, which the stretch passes far "
        "from the origin, so the estimate is no bound";
    static DerivativeBound derivativeFor(Args a) {
        return a.f(6) > 0.5 ? DerivativeBound::None : DerivativeBound::Local;
    }
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"offset", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "b: added."},
        ParamDecl{"linear", ParamType::Float, {4.0, 0.0, 0.0}, -10.0, 10.0, "s4: times v."},
        ParamDecl{"axis",
                  ParamType::Vec3,
                  {1.0, 1.0, 1.0},
                  -4.0,
                  4.0,
                  "a: the turn's axis (not normalised), and "
                  "added to s2 v."},
        ParamDecl{"quadratic", ParamType::Float, {2.0, 0.0, 0.0}, -10.0, 10.0, "s2: times v in the product."},
        ParamDecl{"angle", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "The turn, in multiples of pi."},
        ParamDecl{"scale", ParamType::Float, {0.25, 0.0, 0.0}, -4.0, 4.0, "s: scales the result."},
        toggleParam("mb2_derivative", false, "On: the running derivative times 4, Mandelbulber2's (no bound)."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float t = 3.14159265358979 * angle, ct = cos(t), st = sin(t);
    vec3 turned = v * ct + cross(axis, v) * st + axis * dot(axis, v) * (1.0 - ct);
    vec3 factor = axis + quadratic * v;
    float la = length(axis);
    float turnNorm = abs(ct) + la * abs(st) + la * la * abs(1.0 - ct);
    p.w *= mb2_derivative > 0.5 ? 4.0
                                : abs(scale) * (abs(linear) + abs(quadratic) * length(turned) + length(factor) * turnNorm);
    p.xyz = (offset + linear * v - factor * turned) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 offset = a.v3(0), axis = a.v3(2);
        const double linear = a.f(1), quadratic = a.f(3), scale = a.f(5);
        const vec3 v = p.xyz;
        const double t = 3.14159265358979 * a.f(4), ct = cos(t), st = sin(t);
        const vec3 turned = v * ct + glm::cross(axis, v) * st + axis * dot(axis, v) * (1.0 - ct);
        const vec3 factor = axis + quadratic * v;
        const double la = length(axis), turnNorm = abs(ct) + la * abs(st) + la * la * abs(1.0 - ct);
        p.w *= a.f(6) > 0.5 ? 4.0
                            : abs(scale) * (abs(linear) + abs(quadratic) * length(turned) + length(factor) * turnNorm);
        p.xyz = (offset + linear * v - factor * turned) * scale;
    }
};

}  // namespace fraktal::blocks
