#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Space deforms. Each may stretch space, so the running derivative is multiplied by a bound of
// the deform's largest singular value at the point: the estimate divided by it stays a lower
// bound (Lipschitz argument, Hart 1996 "Sphere tracing", section 4).

// Modulo tiling: repeat space with the given period per axis. A piecewise translation: it keeps
// distances, so the derivative is unchanged; the object must fit inside one cell.
struct ModTile {
    static constexpr std::string_view id = "mod_tile";
    static constexpr std::string_view label = "Modulo tiling";
    static constexpr std::string_view help = "Repeat space: every coordinate wrapped into [-period/2, period/2).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::array params{
        ParamDecl{"period", ParamType::Vec3, {4.0, 4.0, 4.0}, 0.1, 40.0, "Cell size per axis."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz -= period * floor(p.xyz / period + 0.5);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 period = a.v3(0);
        p.xyz -= period * glm::floor(p.xyz / period + 0.5);
    }
};

// Twist about the y axis: rotate x,z by k y radians. The Jacobian is R (I + u e_y^T) with
// |u| = |k| rxz, so its norm is at most 1 + |k| rxz.
struct Twist {
    static constexpr std::string_view id = "twist_y";
    static constexpr std::string_view label = "Twist";
    static constexpr std::string_view help = "Twist about the y axis by `rate` radians per unit of y.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"rate", ParamType::Float, {0.5, 0.0, 0.0}, -4.0, 4.0, "Twist in radians per unit of height."},
    };

    static constexpr std::string_view glsl = R"(
    float s = sin(rate * p.y), co = cos(rate * p.y);
    p.xz = vec2(co * p.x - s * p.z, s * p.x + co * p.z);
    p.w *= 1.0 + abs(rate) * length(p.xz);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double rate = a.f(0);
        double s = sin(rate * p.xyz.y), co = cos(rate * p.xyz.y);
        const double x = p.xyz.x, z = p.xyz.z;
        p.xyz.x = co * x - s * z, p.xyz.z = s * x + co * z;
        p.w *= 1.0 + abs(rate) * std::hypot(p.xyz.x, p.xyz.z);
    }
};

// Bend about the z axis: rotate x,y by k x radians; the same bound as the twist, with rxy.
struct Bend {
    static constexpr std::string_view id = "bend_z";
    static constexpr std::string_view label = "Bend";
    static constexpr std::string_view help = "Bend in the x-y plane by `rate` radians per unit of x.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"rate", ParamType::Float, {0.3, 0.0, 0.0}, -4.0, 4.0, "Bend in radians per unit of x."},
    };

    static constexpr std::string_view glsl = R"(
    float s = sin(rate * p.x), co = cos(rate * p.x);
    p.xy = vec2(co * p.x - s * p.y, s * p.x + co * p.y);
    p.w *= 1.0 + abs(rate) * length(p.xy);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double rate = a.f(0);
        double s = sin(rate * p.xyz.x), co = cos(rate * p.xyz.x);
        const double x = p.xyz.x, y = p.xyz.y;
        p.xyz.x = co * x - s * y, p.xyz.y = s * x + co * y;
        p.w *= 1.0 + abs(rate) * std::hypot(p.xyz.x, p.xyz.y);
    }
};

}  // namespace fraktal::blocks
