#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// visual.bermarte's abs variant of Kali's Mandelbulb (Mandelbulber2's mandelbulb_bermarte,
// MandelbulbBermarteIteration in fractal_formulas.cpp of 2.20; reference fractalforums.com,
// "Mandelbulb variant"). Two measurements of the point's angles, with r = |v| throughout:
// the first turns the point on its sphere, theta = asin(z / r) + theta_offset and
// phi = atan2(y, x) + phi_offset, theta times n theta_scale, u = r (cos t sin f, cos f cos t, sin t)
// (with `acos_first`: acos(z / r), atan(y / x) and u = r (sin t cos f, sin f sin t, cos t)); then
// |x|, |y|, |z| where `abs_between` says; the second measures u again, theta = asin(z / r) +
// theta_offset_second, phi = atan2(y, x) times n phi_scale (theta is not raised), and the result is
// r^n times the point of those angles in the same form (`acos_second` as acos_first). Unlike
// Kali's multi bulb (mandelbulb_kali_multi), neither angle of the second measurement adds the
// first's. The running derivative takes Mandelbulber2's n r^(n-1) (c's +1 comes from add_c); the
// first measurement's stretch of the latitude by n theta_scale is left out as Mandelbulber2 leaves
// it, so `fraktal check` measures the step factor. acos(z / r) and asin(z / r) are taken as the
// angles of (|xy|, z), the same values without their loss of digits near +-1 in single precision.
struct MandelbulbBermarte {
    static constexpr std::string_view id = "mandelbulb_bermarte";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb, Bermarte";
    static constexpr std::string_view help =
        "visual.bermarte's abs variant of Kali's Mandelbulb: the point turned on its sphere by its latitude "
        "times n theta_scale, chosen axes made absolute, then raised to n with its azimuth times n phi_scale.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps across the atan2 seams of both measurements and where abs folds the turned point";
    static constexpr Degree degree{"power"};
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 16.0, "Exponent n."},
        ParamDecl{"theta_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies n on the first theta."},
        ParamDecl{"phi_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies n on the second phi."},
        ParamDecl{"theta_offset",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to the first theta before the scale, degrees."},
        ParamDecl{"phi_offset", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to the first phi, degrees."},
        ParamDecl{"theta_offset_second",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to the second theta, degrees."},
        toggleParam("acos_first", false, "On: the first measurement by acos and atan of the quotient (cosine form)."),
        toggleParam("acos_second", false, "On: the second measurement by acos and atan of the quotient (cosine form)."),
        ParamDecl{"abs_between",
                  ParamType::Vec3,
                  {1.0, 1.0, 1.0},
                  0.0,
                  1.0,
                  "Per axis, 1: the absolute value between the two measurements."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        vec3 v = p.xyz;
        float lat = length(v.xy);
        float th, ph;
        if (acos_first > 0.5) {
            th = (atan(lat, v.z) + radians(theta_offset)) * power * theta_scale;
            ph = atan(v.y / v.x) + radians(phi_offset);
            v = r * vec3(sin(th) * cos(ph), sin(ph) * sin(th), cos(th));
        } else {
            th = (atan(v.z, lat) + radians(theta_offset)) * power * theta_scale;
            ph = atan(v.y, v.x) + radians(phi_offset);
            v = r * vec3(cos(th) * sin(ph), cos(ph) * cos(th), sin(th));
        }
        v = mix(v, abs(v), greaterThan(abs_between, vec3(0.5)));
        lat = length(v.xy);
        float zp = pow(r, power);
        if (acos_second > 0.5) {
            th = atan(lat, v.z) + radians(theta_offset_second);
            ph = atan(v.y / v.x) * power * phi_scale;
            v = zp * vec3(sin(th) * cos(ph), sin(ph) * sin(th), cos(th));
        } else {
            th = atan(v.z, lat) + radians(theta_offset_second);
            ph = atan(v.y, v.x) * power * phi_scale;
            v = zp * vec3(cos(th) * sin(ph), cos(ph) * cos(th), sin(th));
        }
        p.w *= power * pow(r, power - 1.0);
        p.xyz = v;
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0), theta_scale = a.f(1), phi_scale = a.f(2);
        const vec3 absBetween = a.v3(8);
        const double r = length(p.xyz);
        if (!(r > 0.0)) {
            p.w = 0.0;
            return;
        }
        vec3 v = p.xyz;
        double lat = std::hypot(v.x, v.y), th, ph;
        if (a.f(6) > 0.5) {
            th = (std::atan2(lat, v.z) + glm::radians(a.f(3))) * power * theta_scale;
            ph = std::atan(v.y / v.x) + glm::radians(a.f(4));
            v = r * vec3(std::sin(th) * std::cos(ph), std::sin(ph) * std::sin(th), std::cos(th));
        } else {
            th = (std::atan2(v.z, lat) + glm::radians(a.f(3))) * power * theta_scale;
            ph = std::atan2(v.y, v.x) + glm::radians(a.f(4));
            v = r * vec3(std::cos(th) * std::sin(ph), std::cos(ph) * std::cos(th), std::sin(th));
        }
        for (int k = 0; k < 3; ++k)
            if (absBetween[k] > 0.5) v[k] = std::abs(v[k]);
        lat = std::hypot(v.x, v.y);
        const double zp = std::pow(r, power);
        if (a.f(7) > 0.5) {
            th = std::atan2(lat, v.z) + glm::radians(a.f(5));
            ph = std::atan(v.y / v.x) * power * phi_scale;
            v = zp * vec3(std::sin(th) * std::cos(ph), std::sin(ph) * std::sin(th), std::cos(th));
        } else {
            th = std::atan2(v.z, lat) + glm::radians(a.f(5));
            ph = std::atan2(v.y, v.x) * power * phi_scale;
            v = zp * vec3(std::cos(th) * std::sin(ph), std::cos(ph) * std::cos(th), std::sin(th));
        }
        p.w *= power * std::pow(r, power - 1.0);
        p.xyz = v;
    }
};

}  // namespace fraktal::blocks
