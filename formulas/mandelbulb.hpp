#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// The Mandelbulb power step in the seed's exact convention (2.2.2): r = |v|,
// theta = acos(y / r), phi = atan2(x, z), v -> S(r^n, n theta, n phi), where S maps back with
// y = r cos(theta), x = r sin(theta) sin(phi), z = r sin(theta) cos(phi).
// theta is computed as atan2(sqrt(x^2 + z^2), y), which equals acos(y / r) but keeps its
// precision near the poles, where acos loses it in single precision.
// Running derivative: dr -> n r^(n-1) s dr (add_c adds the +1), where s = max(1, |sin(n theta) /
// sin(theta)|) makes it the Jacobian's largest singular value, a Lipschitz bound. In spherical
// coordinates the map is (r, theta, phi) -> (r^n, n theta, n phi); a step along r or theta is
// stretched by n r^(n-1), a step along phi (arc r sin(theta) dphi) by n r^(n-1) sin(n theta) /
// sin(theta), up to n times more near the poles. The scalar n r^(n-1) alone (White/Nylander;
// Syntopia, "Distance estimated 3D fractals" part V) made the log estimate overshoot 1.7x at
// 12 iterations on orbits that pass near the y axis (`fraktal check presets/mandelbulb.json`).
// |sin(n theta)| <= n |sin(theta)| for integer n, so s <= n; s is clamped to n, which is also its
// limit on the axis (sin(theta) = 0, where the quotient is 0 / 0) and holds it finite for
// non-integer n, whose map jumps at theta = pi anyway.
struct Mandelbulb {
    static constexpr std::string_view id = "mandelbulb";
    static constexpr std::string_view label = "Mandelbulb power";
    static constexpr std::string_view help =
        "Raises each point to a power in spherical coordinates: power 8 makes the classic Mandelbulb.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{"power"};
    static DerivativeBound derivativeFor(Args a) { return sphericalPowerBound(a.f(0)); }
    static constexpr std::string_view jump = kNonIntegerPowerSeam;
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 32.0, "Exponent n; 8 is the classic bulb."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        float theta = atan(length(p.xz), p.y);
        float sinTheta = abs(sin(theta)), sinPowerTheta = abs(sin(power * theta));
        float phiStretch = sinPowerTheta < power * sinTheta ? max(1.0, sinPowerTheta / sinTheta) : power;
        theta *= power;
        float phi = atan(p.x, p.z) * power;
        p.w *= power * pow(r, power - 1.0) * phiStretch;
        p.xyz = pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0);
        double r = length(p.xyz);
        if (r > 0.0) {
            double theta = std::atan2(std::hypot(p.xyz.x, p.xyz.z), p.xyz.y);
            double sinTheta = abs(sin(theta)), sinPowerTheta = abs(sin(power * theta));
            double phiStretch = sinPowerTheta < power * sinTheta ? max(1.0, sinPowerTheta / sinTheta) : power;
            theta *= power;
            double phi = std::atan2(p.xyz.x, p.xyz.z) * power;
            p.w *= power * std::pow(r, power - 1.0) * phiStretch;
            p.xyz = std::pow(r, power) * vec3(sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi));
        } else {
            p.w = 0.0;
        }
    }
};

}  // namespace fraktal::blocks
