#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulb variants that artists know from Mandelbulber2. All are spherical power maps
// v -> r^n S(n theta + theta_phase, n phi + phi_phase); their running derivative is the
// analytic scalar one, dr -> n r^(n-1) dr (White/Nylander, Syntopia part V), which
// underestimates the stretch near the poles (the classic bulb, mandelbulb.hpp, bounds it).

// The seed's bulb (mandelbulb.hpp) with phase offsets added to the multiplied angles.
struct MandelbulbPhase {
    static constexpr std::string_view id = "mandelbulb_phase";
    static constexpr std::string_view label = "Mandelbulb with phase";
    static constexpr std::string_view help =
        "Mandelbulb power with theta and phi phase offsets (degrees) added after the multiplication.";
    static constexpr Category category = Category::Power;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
        ParamDecl{"theta_phase", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to n theta, degrees."},
        ParamDecl{"phi_phase", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to n phi, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(length(p.xz), p.y) * power + radians(theta_phase);
        float phi = atan(p.x, p.z) * power + radians(phi_phase);
        p.w *= power * pow(r, power - 1.0);
        p.xyz = pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0), theta_phase = a.f(1), phi_phase = a.f(2);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(std::hypot(p.xyz.x, p.xyz.z), p.xyz.y) * power + glm::radians(theta_phase);
            double phi = std::atan2(p.xyz.x, p.xyz.z) * power + glm::radians(phi_phase);
            p.w *= power * std::pow(r, power - 1.0);
            p.xyz = std::pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
        } else {
            p.w = 0.0;
        }
    }
};

// "Sine" bulb: theta is the latitude asin(z / r) (computed as atan2(z, rxy)), phi = atan2(y, x);
// x = r^n cos(n theta) cos(n phi), y = r^n cos(n theta) sin(n phi), z = r^n sin(n theta).
struct MandelbulbSine {
    static constexpr std::string_view id = "mandelbulb_sine";
    static constexpr std::string_view label = "Mandelbulb (sine)";
    static constexpr std::string_view help = "Mandelbulb with latitude theta = asin(z/r): z = r^n sin(n theta).";
    static constexpr Category category = Category::Power;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(p.z, length(p.xy)) * power;
        float phi = atan(p.y, p.x) * power;
        p.w *= power * pow(r, power - 1.0);
        p.xyz = pow(r, power) * vec3(cos(theta) * cos(phi), cos(theta) * sin(phi), sin(theta));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(p.xyz.z, std::hypot(p.xyz.x, p.xyz.y)) * power;
            double phi = std::atan2(p.xyz.y, p.xyz.x) * power;
            p.w *= power * std::pow(r, power - 1.0);
            p.xyz = std::pow(r, power) * vec3(cos(theta) * cos(phi), cos(theta) * sin(phi), sin(theta));
        } else {
            p.w = 0.0;
        }
    }
};

// "Cosine" bulb: theta is the polar angle acos(z / r) (computed as atan2(rxy, z)),
// phi = atan2(y, x); x = r^n sin(n theta) cos(n phi), y = r^n sin(n theta) sin(n phi),
// z = r^n cos(n theta): the White/Nylander bulb with z as its pole.
struct MandelbulbCosine {
    static constexpr std::string_view id = "mandelbulb_cosine";
    static constexpr std::string_view label = "Mandelbulb (cosine)";
    static constexpr std::string_view help = "Mandelbulb with polar theta = acos(z/r): z = r^n cos(n theta).";
    static constexpr Category category = Category::Power;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(length(p.xy), p.z) * power;
        float phi = atan(p.y, p.x) * power;
        p.w *= power * pow(r, power - 1.0);
        p.xyz = pow(r, power) * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(std::hypot(p.xyz.x, p.xyz.y), p.xyz.z) * power;
            double phi = std::atan2(p.xyz.y, p.xyz.x) * power;
            p.w *= power * std::pow(r, power - 1.0);
            p.xyz = std::pow(r, power) * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
        } else {
            p.w = 0.0;
        }
    }
};

// Bristorbrot (Doug Bristor; Mandelbulber2 bristorbrot): a quadratic, Riemann-type power
// x' = x^2 - y^2 - z^2, y' = y (2x - z), z' = z (2x + y). Its Jacobian grows like r; the
// derivative follows the degree-2 rule dr -> 2 r dr, as Mandelbulber does, and `fraktal check`
// measures the step factor that keeps the result conservative.
struct Bristorbrot {
    static constexpr std::string_view id = "bristorbrot";
    static constexpr std::string_view label = "Bristorbrot";
    static constexpr std::string_view help = "Quadratic hypercomplex power: (x^2 - y^2 - z^2, y (2x - z), z (2x + y)).";
    static constexpr Category category = Category::Power;
    static constexpr std::array params{
        ParamDecl{"twist",
                  ParamType::Float,
                  {1.0, 0.0, 0.0},
                  -2.0,
                  2.0,
                  "Weight of the cross terms -z and +y (1: Bristor's)."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    p.w *= 2.0 * r;
    p.xyz = vec3(p.x * p.x - p.y * p.y - p.z * p.z, p.y * (2.0 * p.x - twist * p.z), p.z * (2.0 * p.x + twist * p.y));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double twist = a.f(0);
        double r = length(p.xyz);
        p.w *= 2.0 * r;
        const vec3 v = p.xyz;
        p.xyz =
            vec3(v.x * v.x - v.y * v.y - v.z * v.z, v.y * (2.0 * v.x - twist * v.z), v.z * (2.0 * v.x + twist * v.y));
    }
};

}  // namespace fraktal::blocks
