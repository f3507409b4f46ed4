#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The Mandelbulb power step in the seed's exact convention (2.2.2): r = |v|,
// theta = acos(y / r), phi = atan2(x, z), v -> S(r^n, n theta, n phi), where S maps back with
// y = r cos(theta), x = r sin(theta) sin(phi), z = r sin(theta) cos(phi).
// theta is computed as atan2(sqrt(x^2 + z^2), y), which equals acos(y / r) but keeps its
// precision near the poles, where acos loses it in single precision.
// Running derivative (White/Nylander, Syntopia part V): dr -> n r^(n-1) dr; add_c adds the +1.
struct Mandelbulb {
    static constexpr std::string_view id = "mandelbulb";
    static constexpr std::string_view label = "Mandelbulb power";
    static constexpr std::string_view help =
        "Spherical power v -> v^n (seed convention: theta = acos(y/r), phi = atan2(x, z)).";
    static constexpr Category category = Category::Power;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n; 8 is the classic bulb."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(length(p.xz), p.y) * power;
        float phi = atan(p.x, p.z) * power;
        p.w *= power * pow(r, power - 1.0);
        p.xyz = pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(std::hypot(p.xyz.x, p.xyz.z), p.xyz.y) * power;
            double phi = std::atan2(p.xyz.x, p.xyz.z) * power;
            p.w *= power * std::pow(r, power - 1.0);
            p.xyz = std::pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
        } else {
            p.w = 0.0;
        }
    }
};

}  // namespace fraktal::blocks
