#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// msltoe's Riemann sphere fractals (Mandelbulber2's riemann_sphere_msltoe, _v1 and _v2,
// fractal_formulas.cpp; fractalforums.com "riemann fractals", "revisiting the Riemann sphere",
// "alternate co-ordinate systems"). Each puts the point on the sphere of radius `scale`, projects
// it stereographically to a plane (s, t), folds or turns the plane and lifts it back, with the
// radius raised. The stereographic map's stretch runs to infinity at the projection's pole, and
// the folds wrap, so the maps jump: the running derivative is Mandelbulber2's estimate (its delta
// DE for the first) and `fraktal check` measures the step factor.

// riemann_sphere_msltoe: the plane folded by s -> |sin(pi s + s_phase)| (and t), lifted back to
// the unit sphere, at radius r^(2 p) - 1/4 with p = 1 + s^2 + t^2 (at most 36) before the fold.
// r^(2 p) is held below e^40 (2e17), as its stretch: any bailout is passed long before, and single
// precision keeps the square of the result (r^72 of a point at r = 4 does not fit a float).
struct RiemannSphere {
    static constexpr std::string_view id = "riemann_sphere";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Riemann sphere";
    static constexpr std::string_view help =
        "msltoe's Riemann sphere: project to the plane, fold it by |sin|, lift back at radius r^(2p) - 1/4.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps at the projection's pole (z = scale), where s and t run to infinity and their sines do not "
        "settle";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Radius of the projection's sphere."},
        ParamDecl{"s_phase", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Added to pi s before its sine, radians."},
        ParamDecl{"t_phase", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Added to pi t before its sine, radians."},
    };

    static constexpr std::string_view glsl = R"(
    float r = max(length(p.xyz), 1e-20);
    vec3 v = p.xyz * (scale / r);
    float q = 1.0 / (1.0 - v.z);
    float s = v.x * q, t = v.y * q;
    float power = min(1.0 + s * s + t * t, 36.0);
    s = abs(sin(3.14159265358979 * s + s_phase));
    t = abs(sin(3.14159265358979 * t + t_phase));
    float logR = log(r);
    float radius = exp(min(2.0 * power * logR, 40.0)) - 0.25;
    p.w *= 2.0 * power * exp(min((2.0 * power - 1.0) * logR, 40.0));
    p.xyz = vec3(2.0 * s, 2.0 * t, -1.0 + s * s + t * t) * (radius / (1.0 + s * s + t * t));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), s_phase = a.f(1), t_phase = a.f(2);
        double r = std::max(length(p.xyz), 1e-20);
        vec3 v = p.xyz * (scale / r);
        double q = 1.0 / (1.0 - v.z);
        double s = v.x * q, t = v.y * q;
        double power = std::min(1.0 + s * s + t * t, 36.0);
        s = abs(sin(3.14159265358979 * s + s_phase));
        t = abs(sin(3.14159265358979 * t + t_phase));
        double logR = std::log(r);
        double radius = std::exp(std::min(2.0 * power * logR, 40.0)) - 0.25;
        p.w *= 2.0 * power * std::exp(std::min((2.0 * power - 1.0) * logR, 40.0));
        p.xyz = vec3(2.0 * s, 2.0 * t, -1.0 + s * s + t * t) * (radius / (1.0 + s * s + t * t));
    }
};

// riemann_sphere_msltoe_v1: the plane tiled (s and t less their nearest integer), the height
// (r - 3/2)(1 + s^2 + t^2), each scaled by `multiplier`. The running derivative is Mandelbulber2's
// analytic one, 4 scale |v'| / r.
struct RiemannSphereV1 {
    static constexpr std::string_view id = "riemann_sphere_v1";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Riemann sphere V1";
    static constexpr std::string_view help =
        "msltoe's Riemann sphere V1: project to the plane, tile it, and lift by (r - 3/2)(1 + s^2 + t^2).";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where the tiling wraps s or t at a half integer, and at the projection's pole";
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Radius of the projection's sphere."},
        ParamDecl{"multiplier", ParamType::Vec3, {4.0, 4.0, 1.0}, -10.0, 10.0, "Factor for s, t and the height."},
    };

    static constexpr std::string_view glsl = R"(
    float r = max(length(p.xyz), 1e-20);
    vec3 v = p.xyz * (scale / r);
    float q = 1.0 / (1.0 - v.z);
    vec3 plane = vec3(v.x * q, v.y * q, 0.0);
    plane.z = (r - 1.5) * (1.0 + plane.x * plane.x + plane.y * plane.y);
    plane.xy -= floor(plane.xy + 0.5);
    p.xyz = plane * multiplier;
    p.w *= 4.0 * scale * length(p.xyz) / r;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0);
        const vec3 multiplier = a.v3(1);
        double r = std::max(length(p.xyz), 1e-20);
        vec3 v = p.xyz * (scale / r);
        double q = 1.0 / (1.0 - v.z);
        vec3 plane = vec3(v.x * q, v.y * q, 0.0);
        plane.z = (r - 1.5) * (1.0 + plane.x * plane.x + plane.y * plane.y);
        plane.x -= floor(plane.x + 0.5), plane.y -= floor(plane.y + 0.5);
        p.xyz = plane * multiplier;
        p.w *= 4.0 * scale * length(p.xyz) / r;
    }
};

// riemann_sphere_msltoe_v2: projected from the y pole, each plane coordinate's angle
// 2 atan2(2 u, u^2 - 1) is multiplied by 8 (and by theta_scale, phi_scale), lifted back with
// tan(angle / 2), at radius r^4, plus `offset`. The running derivative is Mandelbulber2's,
// 8 scale |v'| / r. Mandelbulber2 writes tan(angle / 2) as sin / (1 + cos), which single
// precision makes infinite within 3e-4 of an odd multiple of pi (cos rounds to -1 there); tan
// stays finite, and the lift takes its large values to the pole (0, 1, 0) as it should.
struct RiemannSphereV2 {
    static constexpr std::string_view id = "riemann_sphere_v2";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Riemann sphere V2";
    static constexpr std::string_view help =
        "msltoe's Riemann sphere V2: the plane's angles multiplied by 8, lifted back at radius r^4, plus offset.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps across atan2's cut unless the angle scales are whole numbers, and where tan(angle / 2) "
        "passes infinity";
    static constexpr Degree degree{{}, 4.0};
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {0.8, 0.0, 0.0}, 0.01, 10.0, "Radius of the projection's sphere."},
        ParamDecl{"theta_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the x angle."},
        ParamDecl{"phi_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the z angle."},
        ParamDecl{"offset", ParamType::Vec3, {0.0, 1.0, 0.0}, -10.0, 10.0, "Added after the step."},
    };

    static constexpr std::string_view glsl = R"(
    float r = max(length(p.xyz), 1e-20);
    vec3 v = p.xyz * (scale / r);
    float rx = v.x / (v.y - 1.0), rz = v.z / (v.y - 1.0);
    float theta = 8.0 * atan(2.0 * rx, rx * rx - 1.0) * theta_scale;
    float phi = 8.0 * atan(2.0 * rz, rz * rz - 1.0) * phi_scale;
    rx = tan(0.5 * theta);
    rz = tan(0.5 * phi);
    float rxz = rx * rx + rz * rz, d = 2.0 / (rxz + 1.0), r4 = r * r * r * r;
    p.xyz = vec3(rx * d, (rxz - 1.0) * 0.5 * d, rz * d) * r4 + offset;
    p.w *= 8.0 * scale * length(p.xyz) / r;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), theta_scale = a.f(1), phi_scale = a.f(2);
        const vec3 offset = a.v3(3);
        double r = std::max(length(p.xyz), 1e-20);
        vec3 v = p.xyz * (scale / r);
        double rx = v.x / (v.y - 1.0), rz = v.z / (v.y - 1.0);
        double theta = 8.0 * std::atan2(2.0 * rx, rx * rx - 1.0) * theta_scale;
        double phi = 8.0 * std::atan2(2.0 * rz, rz * rz - 1.0) * phi_scale;
        rx = std::tan(0.5 * theta);
        rz = std::tan(0.5 * phi);
        double rxz = rx * rx + rz * rz, d = 2.0 / (rxz + 1.0), r4 = r * r * r * r;
        p.xyz = vec3(rx * d, (rxz - 1.0) * 0.5 * d, rz * d) * r4 + offset;
        p.w *= 8.0 * scale * length(p.xyz) / r;
    }
};

// msltoe's Riemann bulb, mod 2 (Mandelbulber2's riemann_bulb_msltoe_mod2): inside the sphere of
// radius^2 about the origin (|v|^2 < radius^2) the point is scaled, smoothly by
// radius 1.18 inside_scale (0.1 |v|^2 + 0.4) / |v|^2 or by `inside_multiplier` per axis; outside it
// is scaled per axis by `multiplier`, inverted in the unit sphere about (0, shift, 0) (w / |w|^2),
// scaled by `scale`, y moved by y_offset, then with `tile` x and z wrapped to their remainder after
// rounding (C's round), with `sine` made |sin(pi sine_scale x)| and the same of z. The running
// derivative is the largest stretch of the branch taken (the inversion's 1 / |w|^2 times the
// multiplier's and the scale's, the sine's pi |sine_scale|); the sphere's edge and the wrap jump.
struct RiemannBulb {
    static constexpr std::string_view id = "riemann_bulb";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Riemann bulb";
    static constexpr std::string_view help =
        "Inside a sphere the point scaled; outside it inverted about (0, shift, 0), scaled, moved up and tiled in x "
        "and z.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps at the inner sphere's edge and where x or z wrap";
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {0.5, 0.0, 0.0}, 0.0, 4.0, "Its square is the inner sphere's radius."},
        toggleParam("smooth_inside", true, "On: the smooth scale inside; off: inside_multiplier."),
        ParamDecl{"inside_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Scales the smooth scale inside."},
        ParamDecl{"inside_multiplier", ParamType::Vec3, {1.0, 1.0, 1.0}, -4.0, 4.0, "Scale per axis inside."},
        ParamDecl{"multiplier", ParamType::Vec3, {2.0, 2.0, 2.0}, -8.0, 8.0, "Scale per axis outside."},
        ParamDecl{"shift", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "y of the inversion's centre."},
        ParamDecl{"scale", ParamType::Float, {3.0, 0.0, 0.0}, -10.0, 10.0, "Scales the inverted point."},
        ParamDecl{"y_offset", ParamType::Float, {1.5, 0.0, 0.0}, -4.0, 4.0, "Added to y after the inversion."},
        toggleParam("tile", true, "On: x and z wrapped to their remainder after rounding."),
        toggleParam("sine", false, "On: x and z made |sin(pi sine_scale v)|."),
        ParamDecl{"sine_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "The sine's frequency."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float rr = dot(v, v);
    if (rr < radius * radius) {
        if (smooth_inside > 0.5) {
            float k = radius * 1.18 * inside_scale;
            p.w *= abs(k) * (0.1 + 0.4 / max(rr, 1e-30));
            v *= k * (rr * 0.1 + 0.4) / max(rr, 1e-30);
        } else {
            p.w *= max(abs(inside_multiplier.x), max(abs(inside_multiplier.y), abs(inside_multiplier.z)));
            v *= inside_multiplier;
        }
    } else {
        vec3 w = v * multiplier - vec3(0.0, shift, 0.0);
        float r1 = max(dot(w, w), 1e-30);
        float stretch = max(abs(multiplier.x), max(abs(multiplier.y), abs(multiplier.z))) * abs(scale) / r1;
        v = w / r1 * scale;
        v.y += y_offset;
        if (tile > 0.5) v.xz -= sign(v.xz) * floor(abs(v.xz) + 0.5);
        if (sine > 0.5) {
            v.xz = abs(sin(3.14159265358979 * v.xz * sine_scale));
            stretch *= max(1.0, 3.14159265358979 * abs(sine_scale));
        }
        p.w *= stretch;
    }
    p.xyz = v;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double radius = a.f(0), inside_scale = a.f(2), shift = a.f(5), scale = a.f(6), y_offset = a.f(7),
                     sine_scale = a.f(10);
        const vec3 inside_multiplier = a.v3(3), multiplier = a.v3(4);
        vec3 v = p.xyz;
        const double rr = dot(v, v);
        if (rr < radius * radius) {
            if (a.f(1) > 0.5) {
                const double k = radius * 1.18 * inside_scale;
                p.w *= abs(k) * (0.1 + 0.4 / std::max(rr, 1e-30));
                v *= k * (rr * 0.1 + 0.4) / std::max(rr, 1e-30);
            } else {
                p.w *= max(abs(inside_multiplier.x), max(abs(inside_multiplier.y), abs(inside_multiplier.z)));
                v *= inside_multiplier;
            }
        } else {
            const vec3 w = v * multiplier - vec3(0.0, shift, 0.0);
            const double r1 = std::max(dot(w, w), 1e-30);
            double stretch = max(abs(multiplier.x), max(abs(multiplier.y), abs(multiplier.z))) * abs(scale) / r1;
            v = w / r1 * scale;
            v.y += y_offset;
            auto wrap = [](double x) { return x - glm::sign(x) * std::floor(abs(x) + 0.5); };
            if (a.f(8) > 0.5) v.x = wrap(v.x), v.z = wrap(v.z);
            if (a.f(9) > 0.5) {
                v.x = abs(sin(3.14159265358979 * v.x * sine_scale));
                v.z = abs(sin(3.14159265358979 * v.z * sine_scale));
                stretch *= max(1.0, 3.14159265358979 * abs(sine_scale));
            }
            p.w *= stretch;
        }
        p.xyz = v;
    }
};

}  // namespace fraktal::blocks
