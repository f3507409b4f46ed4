#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// The complex power iteration z <- z^n + c (seed 2.1.3: "doubling the angle, squaring the radius,
// translating by c"): the Mandelbrot set at n = 2, Multibrot sets for other n, a Julia set when c
// is fixed instead of the pixel. Whole powers multiply in the shader's number type (double on
// fp64 drivers, so deep zooms stay sharp); other powers go through polar form in float, because
// GLSL 4.50 has no double pow/atan/cos. The running derivative bound |dz/dc| <- n|z|^(n-1)|dz| + 1
// feeds the distance estimate (Milnor; Douady-Hubbard potential).
struct Power {
    static constexpr std::string_view id = "power";
    static constexpr std::string_view label = "Complex power";
    static constexpr std::string_view help = "z = z^n + c (Mandelbrot, Multibrot); Julia mode adds a fixed c instead.";
    static constexpr Category category = Category::Power;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {2.0, 0.0, 0.0}, 1.0, 16.0, "Exponent n (any real; whole numbers are exact in double)."},
        toggleParam("julia", false, "On: Julia set (c fixed below); off: Mandelbrot (c = the pixel)."),
        ParamDecl{"julia_x", ParamType::Float, {-0.8, 0.0, 0.0}, -4.0, 4.0, "Julia c, real part."},
        ParamDecl{"julia_y", ParamType::Float, {0.156, 0.0, 0.0}, -4.0, 4.0, "Julia c, imaginary part."},
    };

    static constexpr std::string_view glsl = R"(
    real2 z0 = s.z;
    real r = length(z0);
    if (power == round(power)) {
        real2 w = z0;
        for (int k = 1; k < int(power); ++k) w = real2(w.x * z0.x - w.y * z0.y, w.x * z0.y + w.y * z0.x);
        s.z = w;
    } else {
        vec2 zf = vec2(z0);
        float rn = pow(length(zf), power);
        float th = atan(zf.y, zf.x) * power;
        s.z = real2(rn * cos(th), rn * sin(th));
    }
    real grow = power == 1.0 ? real(1.0) : real(pow(float(r), power - 1.0));
    s.dz = real(power) * grow * s.dz + (julia > 0.5 ? real(0.0) : real(1.0));
    s.z += julia > 0.5 ? real2(julia_x, julia_y) : c;
    s.power = power;
)";
    static void apply(PlaneState& s, const real2& c, Args a) {
        const double power = a.f(0), julia = a.f(1), julia_x = a.f(2), julia_y = a.f(3);
        real2 z0 = s.z;
        real r = glm::length(z0);
        if (power == std::round(power)) {
            real2 w = z0;
            for (int k = 1; k < int(power); ++k) w = real2(w.x * z0.x - w.y * z0.y, w.x * z0.y + w.y * z0.x);
            s.z = w;
        } else {
            real rn = std::pow(r, power);
            real th = std::atan2(z0.y, z0.x) * power;
            s.z = real2(rn * std::cos(th), rn * std::sin(th));
        }
        real grow = power == 1.0 ? real(1.0) : real(std::pow(r, power - 1.0));
        s.dz = real(power) * grow * s.dz + (julia > 0.5 ? real(0.0) : real(1.0));
        s.z += julia > 0.5 ? real2(julia_x, julia_y) : c;
        s.power = power;
    }
};

}  // namespace fraktal::plane_blocks
