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

// Quick Dudley's quadratic (Mandelbulber2's quick_dudley, and with per-term multipliers its
// quick_dudley_mod; fractalforums.com "another shot at the holy grail"):
// (a.x x^2 - b.x yz, a.y z^2 + b.y xy, a.z y^2 + b.z xz). The running derivative is Mandelbulber2's
// 2 r, an estimate the check measures against.
struct QuickDudley {
    static constexpr std::string_view id = "quick_dudley";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Quick Dudley";
    static constexpr std::string_view help =
        "Quick Dudley's quadratic map (a.x x^2 - b.x yz, a.y z^2 + b.y xy, a.z y^2 + b.z xz).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"squares", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "Multiplies x^2, z^2 and y^2 (a)."},
        ParamDecl{"products", ParamType::Vec3, {2.0, 2.0, 2.0}, -8.0, 8.0, "Multiplies yz, xy and xz (b)."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    p.w *= 2.0 * length(v);
    p.xyz = vec3(squares.x * v.x * v.x - products.x * v.y * v.z, squares.y * v.z * v.z + products.y * v.x * v.y,
                 squares.z * v.y * v.y + products.z * v.x * v.z);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 squares = a.v3(0), products = a.v3(1);
        vec3 v = p.xyz;
        p.w *= 2.0 * length(v);
        p.xyz = vec3(squares.x * v.x * v.x - products.x * v.y * v.z, squares.y * v.z * v.z + products.y * v.x * v.y,
                     squares.z * v.y * v.y + products.z * v.x * v.z);
    }
};

// David Makin's 3D-2 quadratic (Mandelbulber2's makin3d2; same thread): (x^2 + 2yz, -y^2 - 2xz,
// -z^2 + 2xy). The running derivative is Mandelbulber2's 2 r.
struct Makin3d2 {
    static constexpr std::string_view id = "makin3d2";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Makin 3D-2";
    static constexpr std::string_view help = "David Makin's quadratic map (x^2 + 2yz, -y^2 - 2xz, -z^2 + 2xy).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    p.w *= 2.0 * length(v);
    p.xyz = vec3(v.x * v.x + 2.0 * v.y * v.z, -v.y * v.y - 2.0 * v.x * v.z, -v.z * v.z + 2.0 * v.x * v.y);
)";
    static void apply(P4& p, const vec3&, Args) {
        vec3 v = p.xyz;
        p.w *= 2.0 * length(v);
        p.xyz = vec3(v.x * v.x + 2.0 * v.y * v.z, -v.y * v.y - 2.0 * v.x * v.z, -v.z * v.z + 2.0 * v.x * v.y);
    }
};

// Buddhi's Mandelbulb 3 (Mandelbulber2's mandelbulb3): the angle in the xy plane doubled (the pair
// squared as a complex number, scaled back to its length), then in the xz plane with x's sign
// after the first step and z's sign by x's before it, the whole scaled by r. Undefined where a
// pair is 0; there it is left as it is.
struct Mandelbulb3 {
    static constexpr std::string_view id = "mandelbulb3";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb 3";
    static constexpr std::string_view help =
        "Buddhi's bulb: the angle doubled in the xy plane, then in the xz plane with sign flips, the radius squared.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where x changes sign (the sign flips of its xz step)";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    p.w *= 2.0 * r;
    vec3 v = p.xyz;
    float zSign = v.x < 0.0 ? -1.0 : 1.0;
    float pair = max(length(v.xy), 1e-30);
    v.xy = vec2(v.x * v.x - v.y * v.y, 2.0 * v.x * v.y) / pair;
    float xSign = v.x < 0.0 ? -1.0 : 1.0;
    pair = max(length(v.xz), 1e-30);
    v.xz = vec2((v.x * v.x - v.z * v.z) * xSign, 2.0 * v.x * v.z * zSign) / pair;
    p.xyz = v * r;
)";
    static void apply(P4& p, const vec3&, Args) {
        double r = length(p.xyz);
        p.w *= 2.0 * r;
        vec3 v = p.xyz;
        const double zSign = v.x < 0.0 ? -1.0 : 1.0;
        double pair = std::max(std::hypot(v.x, v.y), 1e-30);
        v = vec3((v.x * v.x - v.y * v.y) / pair, 2.0 * v.x * v.y / pair, v.z);
        const double xSign = v.x < 0.0 ? -1.0 : 1.0;
        pair = std::max(std::hypot(v.x, v.z), 1e-30);
        v = vec3((v.x * v.x - v.z * v.z) * xSign / pair, v.y, 2.0 * v.x * v.z * zSign / pair);
        p.xyz = v * r;
    }
};

}  // namespace fraktal::blocks
