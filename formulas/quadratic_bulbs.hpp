#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Quadratic bulbs from Mandelbulber2's list (fractal_formulas.cpp). Both square the radius, so the
// running derivative is Mandelbulber2's 2 r: the stretch of their doubled angles is estimated, not
// bounded, and `fraktal check` measures the step factor.

// Buddhi's Mandelbulb 2 (Mandelbulber2's mandelbulb2): the angle in the xy plane doubled, then in
// the yz plane, then in the xz plane (each a complex square of the pair scaled back to its length),
// then the whole scaled by r. Undefined where a pair is 0; there it is left as it is.
struct Mandelbulb2 {
    static constexpr std::string_view id = "mandelbulb2";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb 2";
    static constexpr std::string_view help =
        "Buddhi's bulb: the angle doubled in the xy, then yz, then xz plane, the radius squared.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where a pair of coordinates passes through 0";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    p.w *= 2.0 * r;
    vec3 v = p.xyz;
    float pair = max(length(v.xy), 1e-30);
    v /= pair;
    v.xy = vec2(v.x * v.x - v.y * v.y, 2.0 * v.x * v.y);
    v *= pair;
    pair = max(length(v.yz), 1e-30);
    v /= pair;
    v.yz = vec2(v.y * v.y - v.z * v.z, 2.0 * v.y * v.z);
    v *= pair;
    pair = max(length(v.xz), 1e-30);
    v /= pair;
    v.xz = vec2(v.x * v.x - v.z * v.z, 2.0 * v.x * v.z);
    v *= pair;
    p.xyz = v * r;
)";
    static void apply(P4& p, const vec3&, Args) {
        double r = length(p.xyz);
        p.w *= 2.0 * r;
        vec3 v = p.xyz;
        double pair = std::max(std::hypot(v.x, v.y), 1e-30);
        v /= pair;
        v = vec3(v.x * v.x - v.y * v.y, 2.0 * v.x * v.y, v.z);
        v *= pair;
        pair = std::max(std::hypot(v.y, v.z), 1e-30);
        v /= pair;
        v = vec3(v.x, v.y * v.y - v.z * v.z, 2.0 * v.y * v.z);
        v *= pair;
        pair = std::max(std::hypot(v.x, v.z), 1e-30);
        v /= pair;
        v = vec3(v.x * v.x - v.z * v.z, v.y, 2.0 * v.x * v.z);
        v *= pair;
        p.xyz = v * r;
    }
};

// lkmitch's quadratic (Mandelbulber2's lkmitch): (x^2 - 2yz, z^2 + 2xy, y^2 - 2xz).
struct Lkmitch {
    static constexpr std::string_view id = "lkmitch";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "lkmitch";
    static constexpr std::string_view help = "lkmitch's quadratic map (x^2 - 2yz, z^2 + 2xy, y^2 - 2xz).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    p.w *= 2.0 * length(v);
    p.xyz = vec3(v.x * v.x - 2.0 * v.y * v.z, v.z * v.z + 2.0 * v.x * v.y, v.y * v.y - 2.0 * v.x * v.z);
)";
    static void apply(P4& p, const vec3&, Args) {
        vec3 v = p.xyz;
        p.w *= 2.0 * length(v);
        p.xyz = vec3(v.x * v.x - 2.0 * v.y * v.z, v.z * v.z + 2.0 * v.x * v.y, v.y * v.y - 2.0 * v.x * v.z);
    }
};

}  // namespace fraktal::blocks
