#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// msltoe's donut (Mandelbulber2's msltoe_donut, fractal_formulas.cpp MsltoeDonutIteration): the
// ring of radius R about z is cut into `sections` sectors; outside a thin tube about the ring
// (t = (R - rho)^2 + z^2 - thickness^2 > 0.03) the point's sector is turned onto +x, the sector's
// ring point moved to the origin, and the result scaled by `factor` with y and z swapped (each
// sector's piece of the ring holds the whole again); inside the tube it is divided by t. Mandelbulber2 estimates its
// distance by differences (escape_linear_gradient); the running derivative here bounds the step's Jacobian, |factor|
// outside the tube and, for v / t inside, 1 / |t| + |v| |grad t| / t^2 with |grad t| = 2 sqrt(t + thickness^2). The map
// jumps between sectors and at the tube's edge.
struct MsltoeDonut {
    static constexpr std::string_view id = "msltoe_donut";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe donut";
    static constexpr std::string_view help =
        "Rings of rings: each sector of the ring about z is moved to the centre and scaled; inside a thin tube, "
        "divided by t.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps between the ring's sectors and at the tube's edge";
    static constexpr std::array params{
        ParamDecl{"ring_radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Radius R of the ring about z."},
        ParamDecl{"thickness", ParamType::Float, {0.1, 0.0, 0.0}, 0.0, 4.0, "Radius of the tube about the ring."},
        ParamDecl{"sections", ParamType::Float, {9.0, 0.0, 0.0}, 1.0, 64.0, "Sectors the ring is cut into."},
        ParamDecl{"factor", ParamType::Float, {3.0, 0.0, 0.0}, -10.0, 10.0, "Scale of each sector's copy."},
    };

    static constexpr std::string_view glsl = R"(
    float sector = 6.28318530717959 / sections;
    float rho = length(p.xy), toRing = ring_radius - rho;
    float t = toRing * toRing + p.z * p.z - thickness * thickness;
    float turn = p.x == 0.0 && p.y == 0.0 ? 0.0 : sector * floor(atan(p.y, p.x) / sector + 0.5);
    if (t > 0.03) {
        float c1 = cos(turn), s1 = sin(turn);
        vec3 v = vec3(c1 * p.x + s1 * p.y - ring_radius, -s1 * p.x + c1 * p.y, p.z);
        p.xyz = factor * v.xzy;
        p.w *= abs(factor);
    } else {
        float grad = 2.0 * sqrt(max(t + thickness * thickness, 0.0));
        p.w *= 1.0 / abs(t) + length(p.xyz) * grad / (t * t);
        p.xyz /= t;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double ring_radius = a.f(0), thickness = a.f(1), sections = a.f(2), factor = a.f(3);
        double sector = 6.28318530717959 / sections;
        double rho = std::hypot(p.xyz.x, p.xyz.y), toRing = ring_radius - rho;
        double t = toRing * toRing + p.xyz.z * p.xyz.z - thickness * thickness;
        double turn =
            p.xyz.x == 0.0 && p.xyz.y == 0.0 ? 0.0 : sector * floor(std::atan2(p.xyz.y, p.xyz.x) / sector + 0.5);
        if (t > 0.03) {
            double c1 = cos(turn), s1 = sin(turn);
            vec3 v = vec3(c1 * p.xyz.x + s1 * p.xyz.y - ring_radius, -s1 * p.xyz.x + c1 * p.xyz.y, p.xyz.z);
            p.xyz = factor * vec3(v.x, v.z, v.y);
            p.w *= abs(factor);
        } else {
            double grad = 2.0 * std::sqrt(std::max(t + thickness * thickness, 0.0));
            p.w *= 1.0 / abs(t) + length(p.xyz) * grad / (t * t);
            p.xyz /= t;
        }
    }
};

// msltoe's sym2 mod (Mandelbulber2's msltoe_sym2_mod, from Mandelbulb3D; fractalforums.com
// "choosing the squaring formula by location"): y and z swapped where |y| < |z|, x negated where
// then y > z, White's power-2 triplex with the xy term times y_scale, plus `add`, then pulled
// towards the origin by `offset` (v (1 - offset / |v|)) and scaled by `scale`. The running
// derivative is Mandelbulber2's 2 r |scale|; the swaps make the map jump.
struct MsltoeSym2Mod {
    static constexpr std::string_view id = "msltoe_sym2_mod";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe sym2 mod";
    static constexpr std::string_view help =
        "Power 2 triplex whose squaring depends on the octant (y, z swapped, x negated), plus add, pulled in by "
        "offset, scaled.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where it swaps y and z (|y| = |z|) and negates x";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"y_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the triplex's y term."},
        ParamDecl{"add", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Added after the power."},
        ParamDecl{"offset", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "Pulls the point this far towards 0."},
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Scales the result."},
    };

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz) * abs(scale);
    vec3 v = abs(p.y) < abs(p.z) ? p.xzy : p.xyz;
    if (v.y > v.z) v.x = -v.x;
    vec3 v2 = v * v;
    float zr = 1.0 - v2.z / max(v2.x + v2.y + v2.z, 1e-30);
    v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * sqrt(v2.x + v2.y)) + add;
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double y_scale = a.f(0), offset = a.f(2), scale = a.f(3);
        const vec3 add = a.v3(1);
        p.w *= 2.0 * length(p.xyz) * abs(scale);
        vec3 v = abs(p.xyz.y) < abs(p.xyz.z) ? vec3(p.xyz.x, p.xyz.z, p.xyz.y) : p.xyz;
        if (v.y > v.z) v.x = -v.x;
        vec3 v2 = v * v;
        double zr = 1.0 - v2.z / std::max(v2.x + v2.y + v2.z, 1e-30);
        v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * std::sqrt(v2.x + v2.y)) + add;
        double len = std::max(length(v), 1e-30);
        p.xyz = v * (1.0 - offset / len) * scale;
    }
};

// eiffie's variant of msltoe's Julia bulb (Mandelbulber2's eiffie_msltoe): the (y, z) plane folded
// into the sector |psi| <= pi / 8 about +y (psi = |mod(atan2(z, y) + 9 pi / 8, pi / 4) - pi / 8|),
// then the sym2 mod's power, add, pull and scale (without its octant swap). The running
// derivative is Mandelbulber2's 2 r |scale|; the sector fold is continuous, the power's latitude
// is not bounded by it.
struct EiffieMsltoe {
    static constexpr std::string_view id = "eiffie_msltoe";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "eiffie msltoe";
    static constexpr std::string_view help =
        "(y, z) folded into a pi/4 sector about +y, then the power 2 triplex plus add, pulled in by offset, scaled.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params = MsltoeSym2Mod::params;

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz) * abs(scale);
    float psi = abs(mod(atan(p.z, p.y) + 3.53429173528852, 0.785398163397448) - 0.392699081698724);
    float yz = length(p.yz);
    vec3 v = vec3(p.x, cos(psi) * yz, sin(psi) * yz);
    vec3 v2 = v * v;
    float zr = 1.0 - v2.z / max(v2.x + v2.y + v2.z, 1e-30);
    v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * sqrt(v2.x + v2.y)) + add;
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double y_scale = a.f(0), offset = a.f(2), scale = a.f(3);
        const vec3 add = a.v3(1);
        p.w *= 2.0 * length(p.xyz) * abs(scale);
        double psi =
            abs(glm::mod(std::atan2(p.xyz.z, p.xyz.y) + 3.53429173528852, 0.785398163397448) - 0.392699081698724);
        double yz = std::hypot(p.xyz.y, p.xyz.z);
        vec3 v = vec3(p.xyz.x, cos(psi) * yz, sin(psi) * yz);
        vec3 v2 = v * v;
        double zr = 1.0 - v2.z / std::max(v2.x + v2.y + v2.z, 1e-30);
        v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * std::sqrt(v2.x + v2.y)) + add;
        double len = std::max(length(v), 1e-30);
        p.xyz = v * (1.0 - offset / len) * scale;
    }
};

}  // namespace fraktal::blocks
