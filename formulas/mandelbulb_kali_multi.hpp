#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Kali's multi Mandelbulb (Mandelbulber2's mandelbulb_kali_multi, MandelbulbKaliMultiIteration in
// formula/opencl/mandelbulb_kali_multi.cl of 2.20): the bulb's angles measured twice. With
// r = |v|, the axes taken in `order` as a = (a1, a2, a3): theta = theta_offset + acos(a1 / r) (or
// asin), phi = phi_offset + atan2(a2, a3) (or atan of the quotient); theta is multiplied by
// n theta_scale and the unit point u of those angles built (cosine form (sin t cos f, sin t sin f,
// cos t), or the sine form (cos t sin f, cos t cos f, sin t)). u's axes in `order_second` give the
// second angles: theta becomes acos(b1) + theta_offset_second (with asin, that is added to the
// first theta instead), phi gains atan2(b2, b3), and only phi is multiplied, by n phi_scale / 2.
// The result is r^n times the point of those angles in its own form. The running derivative takes
// Mandelbulber2's n r^(n-1) (c's +1 comes from add_c); the double measurement's stretch is
// estimated, not bounded, so `fraktal check` measures the step factor. acos(a1 / r) and
// asin(a1 / r) are taken as the angles of (|(a2, a3)|, a1), the same values without acos's and
// asin's loss of digits near +-1 in single precision.
struct MandelbulbKaliMulti {
    static constexpr std::string_view id = "mandelbulb_kali_multi";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb, Kali multi";
    static constexpr std::string_view help =
        "Kali's Mandelbulb: the angles measured twice, each time in a chosen axis order and with acos or "
        "asin, atan2 or atan; sine or cosine forms.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps across the atan2 seams of both measurements and where acos meets asin's range";
    static constexpr Degree degree{"power"};
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 16.0, "Exponent n."},
        ParamDecl{"order",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  0.0,
                  5.0,
                  "Axis order of the first measurement: 0 xyz, 1 xzy, 2 yxz, 3 yzx, 4 zxy, 5 zyx."}
            .labelled("First axis order"),
        ParamDecl{"order_second",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  0.0,
                  5.0,
                  "Axis order of the second measurement (same numbers)."}
            .labelled("Second axis order"),
        toggleParam("theta_asin", false, "On: the first latitude by asin (off: acos).").labelled("First theta by asin"),
        toggleParam("theta_asin_second", false, "On: the second latitude by asin, added to the first (off: acos).")
            .labelled("Second theta by asin"),
        toggleParam("phi_atan", false, "On: the first azimuth by atan of the quotient (off: atan2).")
            .labelled("First phi by atan"),
        toggleParam("phi_atan_second", false, "On: the second azimuth by atan of the quotient (off: atan2).")
            .labelled("Second phi by atan"),
        toggleParam("sine_first", false, "On: the first point in the sine form (off: cosine).")
            .labelled("First point sine form"),
        toggleParam("sine_second", false, "On: the result in the sine form (off: cosine).")
            .labelled("Result sine form"),
        ParamDecl{"theta_scale", ParamType::Float, {1.0, 0.0, 0.0}, -2.0, 2.0, "Multiplies n on the first theta."},
        ParamDecl{"phi_scale", ParamType::Float, {1.0, 0.0, 0.0}, -2.0, 2.0, "Multiplies n / 2 on phi."},
        ParamDecl{"theta_offset",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to the first theta before the power, degrees."},
        ParamDecl{
            "phi_offset", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to phi before the power, degrees."},
        ParamDecl{"theta_offset_second",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to the second theta, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        int k = int(order + 0.5);
        vec3 v = p.xyz;
        vec3 a = k == 1 ? v.xzy : k == 2 ? v.yxz : k == 3 ? v.yzx : k == 4 ? v.zxy : k == 5 ? v.zyx : v;
        float lat = length(a.yz);
        float th = radians(theta_offset) + (theta_asin > 0.5 ? atan(a.x, lat) : atan(lat, a.x));
        float ph = radians(phi_offset) + (phi_atan > 0.5 ? atan(a.y / a.z) : atan(a.y, a.z));
        th *= power * theta_scale;
        v = sine_first > 0.5 ? vec3(cos(th) * sin(ph), cos(ph) * cos(th), sin(th))
                             : vec3(sin(th) * cos(ph), sin(ph) * sin(th), cos(th));
        k = int(order_second + 0.5);
        a = k == 1 ? v.xzy : k == 2 ? v.yxz : k == 3 ? v.yzx : k == 4 ? v.zxy : k == 5 ? v.zyx : v;
        lat = length(a.yz);
        th = theta_asin_second > 0.5 ? th + atan(a.x, lat) + radians(theta_offset_second)
                                     : atan(lat, a.x) + radians(theta_offset_second);
        ph += phi_atan_second > 0.5 ? atan(a.y / a.z) : atan(a.y, a.z);
        ph *= power * phi_scale * 0.5;
        p.w *= power * pow(r, power - 1.0);
        p.xyz = pow(r, power) * (sine_second > 0.5 ? vec3(cos(th) * sin(ph), cos(ph) * cos(th), sin(th))
                                                    : vec3(sin(th) * cos(ph), sin(ph) * sin(th), cos(th)));
    } else {
        p.w = 0.0;
    }
)";
    // The point's axes in one of the six orders (0 xyz ... 5 zyx, Mandelbulber2's numbering).
    static vec3 ordered(const vec3& v, double order) {
        switch (int(order + 0.5)) {
            case 1: return {v.x, v.z, v.y};
            case 2: return {v.y, v.x, v.z};
            case 3: return {v.y, v.z, v.x};
            case 4: return {v.z, v.x, v.y};
            case 5: return {v.z, v.y, v.x};
            default: return v;
        }
    }
    static vec3 angles(double th, double ph, bool sine) {
        return sine ? vec3(cos(th) * sin(ph), cos(ph) * cos(th), sin(th))
                    : vec3(sin(th) * cos(ph), sin(ph) * sin(th), cos(th));
    }
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0), theta_scale = a.f(9), phi_scale = a.f(10);
        const double r = length(p.xyz);
        if (!(r > 0.0)) {
            p.w = 0.0;
            return;
        }
        vec3 u = ordered(p.xyz, a.f(1));
        double lat = std::hypot(u.y, u.z);
        double th = glm::radians(a.f(11)) + (a.f(3) > 0.5 ? std::atan2(u.x, lat) : std::atan2(lat, u.x));
        double ph = glm::radians(a.f(12)) + (a.f(5) > 0.5 ? std::atan(u.y / u.z) : std::atan2(u.y, u.z));
        th *= power * theta_scale;
        u = ordered(angles(th, ph, a.f(7) > 0.5), a.f(2));
        lat = std::hypot(u.y, u.z);
        th = a.f(4) > 0.5 ? th + std::atan2(u.x, lat) + glm::radians(a.f(13))
                          : std::atan2(lat, u.x) + glm::radians(a.f(13));
        ph += a.f(6) > 0.5 ? std::atan(u.y / u.z) : std::atan2(u.y, u.z);
        ph *= power * phi_scale * 0.5;
        p.w *= power * std::pow(r, power - 1.0);
        p.xyz = std::pow(r, power) * angles(th, ph, a.f(8) > 0.5);
    }
};

// Mandelbulber2's multi Mandelbulb (mandelbulb_multi, and the bulb of mandelbulb_multi2;
// fractal_formulas.cpp of 2.20): the bulb's angles measured once. With r = |v| and the axes taken
// in `order` as a = (a1, a2, a3): theta0 = theta_offset + acos(a1 / r) (or asin), phi0 =
// phi_offset + atan2(a2, a3) (or atan of the quotient); theta = n theta_scale theta0, phi = n
// phi_scale phi0; the result r^n (c cos phi, c sin phi, sin theta) with c = cos theta (the sine
// form), or r^n (s sin phi, s cos phi, cos theta) with s = sin theta (the cosine form), c and s
// taken of theta0 with `latitude_unscaled`. The running derivative is Mandelbulber2's n r^(n-1)
// (c's 1 from add_c). acos and asin are taken as angles of (|(a2, a3)|, a1), as in the Kali bulb.
struct MandelbulbMulti {
    static constexpr std::string_view id = "mandelbulb_multi";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb, multi";
    static constexpr std::string_view help =
        "Mandelbulb whose angles are measured in a chosen axis order, with acos or asin, atan2 or atan; sine or "
        "cosine form.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps across the atan2 seam and where atan's quotient changes sign";
    static constexpr Degree degree{"power"};
    static constexpr std::array params{
        ParamDecl{"power", ParamType::Float, {8.0, 0.0, 0.0}, 1.0, 16.0, "Exponent n."},
        ParamDecl{"order",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  0.0,
                  5.0,
                  "Axis order of the measurement: 0 xyz, 1 xzy, 2 yxz, 3 yzx, 4 zxy, 5 zyx."}
            .labelled("Axis order"),
        toggleParam("theta_asin", false, "On: the latitude by asin (off: acos).").labelled("Theta by asin"),
        toggleParam("phi_atan", false, "On: the azimuth by atan of the quotient (off: atan2).").labelled("Phi by atan"),
        toggleParam("cosine", false, "On: the cosine form (s sin phi, s cos phi, cos theta); off: the sine form."),
        toggleParam("latitude_unscaled", false, "On: the horizontal factor of theta before the power multiplies it."),
        ParamDecl{"theta_scale", ParamType::Float, {1.0, 0.0, 0.0}, -2.0, 2.0, "Multiplies n on theta."},
        ParamDecl{"phi_scale", ParamType::Float, {1.0, 0.0, 0.0}, -2.0, 2.0, "Multiplies n on phi."},
        ParamDecl{"theta_offset",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "Added to theta before the power, degrees."},
        ParamDecl{
            "phi_offset", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Added to phi before the power, degrees."},
    };
    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (r > 0.0) {
        int k = int(order + 0.5);
        vec3 v = p.xyz;
        vec3 a = k == 1 ? v.xzy : k == 2 ? v.yxz : k == 3 ? v.yzx : k == 4 ? v.zxy : k == 5 ? v.zyx : v;
        float lat = length(a.yz);
        float th0 = radians(theta_offset) + (theta_asin > 0.5 ? atan(a.x, lat) : atan(lat, a.x));
        float ph = radians(phi_offset) + (phi_atan > 0.5 ? atan(a.y / a.z) : atan(a.y, a.z));
        float th = th0 * power * theta_scale;
        ph *= power * phi_scale;
        float horizontal = latitude_unscaled > 0.5 ? th0 : th;
        p.w *= power * pow(r, power - 1.0);
        p.xyz = pow(r, power) * (cosine > 0.5 ? vec3(sin(horizontal) * sin(ph), cos(ph) * sin(horizontal), cos(th))
                                              : vec3(cos(horizontal) * cos(ph), sin(ph) * cos(horizontal), sin(th)));
    } else {
        p.w = 0.0;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double power = a.f(0), theta_scale = a.f(6), phi_scale = a.f(7);
        const double r = length(p.xyz);
        if (!(r > 0.0)) {
            p.w = 0.0;
            return;
        }
        const vec3 u = MandelbulbKaliMulti::ordered(p.xyz, a.f(1));
        const double lat = std::hypot(u.y, u.z);
        const double th0 = glm::radians(a.f(8)) + (a.f(2) > 0.5 ? std::atan2(u.x, lat) : std::atan2(lat, u.x));
        double ph = glm::radians(a.f(9)) + (a.f(3) > 0.5 ? std::atan(u.y / u.z) : std::atan2(u.y, u.z));
        const double th = th0 * power * theta_scale;
        ph *= power * phi_scale;
        const double horizontal = a.f(5) > 0.5 ? th0 : th;
        p.w *= power * std::pow(r, power - 1.0);
        p.xyz =
            std::pow(r, power) * (a.f(4) > 0.5 ? vec3(sin(horizontal) * sin(ph), cos(ph) * sin(horizontal), cos(th))
                                               : vec3(cos(horizontal) * cos(ph), sin(ph) * cos(horizontal), sin(th)));
    }
};

}  // namespace fraktal::blocks
