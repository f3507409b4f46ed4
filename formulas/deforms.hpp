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
    static constexpr std::string_view jump = "its map jumps where it wraps space into the next cell";
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
// u = k (-z, 0, x) orthogonal to e_y, |u| = |k| rxz; the largest singular value of I + u v^T
// with u orthogonal to the unit v is (|u| + sqrt(|u|^2 + 4)) / 2, under the 1 + |u| of the
// triangle inequality by up to 1.25x per step (at |u| = 1.5).
struct Twist {
    static constexpr std::string_view id = "twist_y";
    static constexpr std::string_view label = "Twist";
    static constexpr std::string_view help = "Twist about the y axis by `rate` radians per unit of y.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr bool stretchGrowsWithRadius = true;  // |u| = |k| rxz
    static constexpr std::array params{
        ParamDecl{"rate", ParamType::Float, {0.5, 0.0, 0.0}, -4.0, 4.0, "Twist in radians per unit of height."},
    };

    static constexpr std::string_view glsl = R"(
    float s = sin(rate * p.y), co = cos(rate * p.y);
    p.xz = vec2(co * p.x - s * p.z, s * p.x + co * p.z);
    float u = abs(rate) * length(p.xz);
    p.w *= 0.5 * (u + sqrt(u * u + 4.0));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double rate = a.f(0);
        double s = sin(rate * p.xyz.y), co = cos(rate * p.xyz.y);
        const double x = p.xyz.x, z = p.xyz.z;
        p.xyz.x = co * x - s * z, p.xyz.z = s * x + co * z;
        const double u = abs(rate) * std::hypot(p.xyz.x, p.xyz.z);
        p.w *= 0.5 * (u + sqrt(u * u + 4.0));
    }
};

// Bend about the z axis: rotate x,y by k x radians. The Jacobian is R (I + u e_x^T) with
// u = k (-y, x, 0), which leans on e_x by a = -k y and across it by b = |k x|: in the plane of e_x
// and u that is [[1 + a, 0], [b, 1]], whose largest singular value is
// (sqrt((2 + a)^2 + b^2) + sqrt(a^2 + b^2)) / 2, and sqrt(a^2 + b^2) = |k| rxy.
struct Bend {
    static constexpr std::string_view id = "bend_z";
    static constexpr std::string_view label = "Bend";
    static constexpr std::string_view help = "Bend in the x-y plane by `rate` radians per unit of x.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr bool stretchGrowsWithRadius = true;  // |k| rxy
    static constexpr std::array params{
        ParamDecl{"rate", ParamType::Float, {0.3, 0.0, 0.0}, -4.0, 4.0, "Bend in radians per unit of x."},
    };

    static constexpr std::string_view glsl = R"(
    float s = sin(rate * p.x), co = cos(rate * p.x);
    p.w *= 0.5 * (length(vec2(2.0 - rate * p.y, rate * p.x)) + abs(rate) * length(p.xy));
    p.xy = vec2(co * p.x - s * p.y, s * p.x + co * p.y);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double rate = a.f(0);
        double s = sin(rate * p.xyz.x), co = cos(rate * p.xyz.x);
        const double x = p.xyz.x, y = p.xyz.y;
        p.w *= 0.5 * (std::hypot(2.0 - rate * y, rate * x) + abs(rate) * std::hypot(x, y));
        p.xyz.x = co * x - s * y, p.xyz.y = s * x + co * y;
    }
};

}  // namespace fraktal::blocks
