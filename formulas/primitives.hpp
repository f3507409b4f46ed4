#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Primitives combined with the fractal. The fractal's part is the IFS-type distance
// (|v| - offset) / |dr| of the orbit's end point (seed 3.2); the primitive's is its exact
// distance at the starting point c. They are joined by a union, an intersection, or, with a
// blend radius k > 0, by Quilez's polynomial smooth minimum
// smin(a, b) = mix(b, a, h) - k h (1 - h), h = clamp(1/2 + (b - a) / 2k, 0, 1)
// (iquilezles.org "smooth minimum"); an intersection is -smin(-a, -b). Inside where <= 0.
// With log_part on, the fractal's part is the log estimate 0.5 log(r) r / |dr| of escape_log
// (power formulas: a Mandelbulb cut by a box), 0 where the orbit did not escape.

// The fractal's part on the CPU (the GLSL bodies below spell it out): the linear estimate, or with
// log_part on the log one.
inline double fractalPart(const P4& p, double offset, double logPart) {
    const double r = length(p.xyz);
    if (logPart <= 0.5) return (r - offset) / abs(p.w);
    return r > 1.0 ? 0.5 * max(std::log(r) - p.surfaceLogR, 0.0) * r / abs(p.w) : 0.0;
}

// The primitive's part g and the fractal's f joined: a union, or with `intersect` on an
// intersection, smoothed over `blend` (the GLSL bodies below spell it out).
inline double joinParts(double g, double f, double intersect, double blend) {
    double k = std::max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
    double h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
    return sgn * (glm::mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
}

struct PlaneCombine {
    static constexpr std::string_view id = "plane_combine";
    static constexpr std::string_view label = "Plane with fractal";
    static constexpr std::string_view help =
        "The fractal joined with a plane n . c = height: union, intersection or smooth union.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{
            "offset", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "The fractal's part: |v| - offset over |dr|."},
        toggleParam("intersect", false, "On: intersection; off: union."),
        ParamDecl{"blend", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 2.0, "Smooth blend radius k (0: sharp)."},
        ParamDecl{"normal", ParamType::Vec3, {0.0, 1.0, 0.0}, -1.0, 1.0, "Plane normal (normalised before use).", true},
        ParamDecl{"height", ParamType::Float, {-1.0, 0.0, 0.0}, -100.0, 100.0, "Plane offset along the normal."},
        toggleParam("log_part", false, "On: the fractal's part is the log estimate (power formulas)."),
    };

    static constexpr std::string_view glsl = R"(
    float g = dot(c, normalize(normal)) - height;
    float r = length(p.xyz);
    float f = log_part > 0.5 ? (r > 1.0 ? 0.5 * max(log(r) - surfaceLogR, 0.0) * r / abs(p.w) : 0.0)
                             : (r - offset) / abs(p.w);
    float k = max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
    float h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
    return sgn * (mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
)";
    static double estimate(const P4& p, const vec3& c, Args a) {
        const double offset = a.f(0), intersect = a.f(1), blend = a.f(2);
        const vec3 normal = a.v3(3);
        const double height = a.f(4);
        double g = dot(c, normalize(normal)) - height;
        const double f = fractalPart(p, offset, a.f(5));
        return joinParts(g, f, intersect, blend);
    }
};

struct SphereCombine {
    static constexpr std::string_view id = "sphere_combine";
    static constexpr std::string_view label = "Sphere with fractal";
    static constexpr std::string_view help =
        "The fractal joined with a sphere about a centre: union, intersection or smooth union.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{
            "offset", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "The fractal's part: |v| - offset over |dr|."},
        toggleParam("intersect", false, "On: intersection; off: union."),
        ParamDecl{"blend", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 2.0, "Smooth blend radius k (0: sharp)."},
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, 0.0}, -100.0, 100.0, "Sphere centre."},
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 100.0, "Sphere radius."},
        toggleParam("log_part", false, "On: the fractal's part is the log estimate (power formulas)."),
    };

    static constexpr std::string_view glsl = R"(
    float g = length(c - center) - radius;
    float r = length(p.xyz);
    float f = log_part > 0.5 ? (r > 1.0 ? 0.5 * max(log(r) - surfaceLogR, 0.0) * r / abs(p.w) : 0.0)
                             : (r - offset) / abs(p.w);
    float k = max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
    float h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
    return sgn * (mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
)";
    static double estimate(const P4& p, const vec3& c, Args a) {
        const double offset = a.f(0), intersect = a.f(1), blend = a.f(2);
        const vec3 center = a.v3(3);
        const double radius = a.f(4);
        double g = length(c - center) - radius;
        const double f = fractalPart(p, offset, a.f(5));
        return joinParts(g, f, intersect, blend);
    }
};

struct BoxCombine {
    static constexpr std::string_view id = "box_combine";
    static constexpr std::string_view label = "Box with fractal";
    static constexpr std::string_view help =
        "The fractal joined with an axis-aligned box about a centre: union, intersection or smooth union.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{
            "offset", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "The fractal's part: |v| - offset over |dr|."},
        toggleParam("intersect", false, "On: intersection; off: union."),
        ParamDecl{"blend", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 2.0, "Smooth blend radius k (0: sharp)."},
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, 0.0}, -100.0, 100.0, "Box centre."},
        ParamDecl{"size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.001, 100.0, "Half-size of the box."},
        toggleParam("log_part", false, "On: the fractal's part is the log estimate (power formulas)."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 q = abs(c - center) - size;
    float g = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
    float r = length(p.xyz);
    float f = log_part > 0.5 ? (r > 1.0 ? 0.5 * max(log(r) - surfaceLogR, 0.0) * r / abs(p.w) : 0.0)
                             : (r - offset) / abs(p.w);
    float k = max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
    float h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
    return sgn * (mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
)";
    static double estimate(const P4& p, const vec3& c, Args a) {
        const double offset = a.f(0), intersect = a.f(1), blend = a.f(2);
        const vec3 center = a.v3(3), size = a.v3(4);
        vec3 q = abs(c - center) - size;
        double g = length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0);
        const double f = fractalPart(p, offset, a.f(5));
        return joinParts(g, f, intersect, blend);
    }
};

// Mandelbulber2's water (primitives.cpp, sPrimitiveWater::PrimitiveDistanceWater): the plane
// z = 0 of a frame turned about `axis` by `angle` about `center`, solid below, raised by a sum of
// `iterations` sine and cosine waves of growing frequency (x 1.872 each), `wave_length` long and
// `amplitude` wave lengths high; `phase` moves them (Mandelbulber2's -anim_speed frame / 10). Within
// ten amplitudes of the plane only, as there; the waves' slope is up to `iterations` x amplitude,
// so the step factor `fraktal check` measures makes it safe.
inline double waterHeight(const vec3& q, double waveLength, double amplitude, double iterations, double phase) {
    double waveX = 0.0, waveY = 0.0, pw = 1.0, p2 = 0.05;
    const double x = q.x / waveLength, y = q.y / waveLength;
    for (int i = 1; i <= int(iterations); ++i) {
        double p3 = pw * p2, shift = phase / (double(i) / 2.697 + 1.0);
        double wx =
            sin(double(i) + 0.4 * waveX * p3 + sin(0.23 * y * p3 + shift * 0.134 * p3) + x * p3 + shift * p3) / pw;
        double wy =
            cos(double(i) + 0.4 * waveY * p3 + sin(x * p3 + shift * 0.0179 * p3) + 0.23 * y * p3 + shift * 0.023 * p3) /
            pw;
        waveX += wx;
        waveY += wy;
        p2 = p2 + (1.0 - p2 + 0.5 * sin(shift * 0.0323)) * 0.7;
        pw *= 1.872;
    }
    return (waveX + waveY) * waveLength * amplitude;
}

struct WaterCombine {
    static constexpr std::string_view id = "water_combine";
    static constexpr std::string_view label = "Water with fractal";
    static constexpr std::string_view help =
        "The fractal joined with a wavy water surface (Mandelbulber2's water): union, intersection or smooth union.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{
            "offset", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "The fractal's part: |v| - offset over |dr|."},
        toggleParam("intersect", false, "On: intersection; off: union."),
        ParamDecl{"blend", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 2.0, "Smooth blend radius k (0: sharp)."},
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, -1.0}, -100.0, 100.0, "A point of the still water's plane."},
        ParamDecl{"axis",
                  ParamType::Vec3,
                  {0.0, 0.0, 1.0},
                  -1.0,
                  1.0,
                  "The axis the water's frame turns about (normalised before use).",
                  true},
        ParamDecl{"angle",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  -180.0,
                  180.0,
                  "The turn in degrees: 0 keeps the water level (solid below z), 180 about x turns it over."},
        ParamDecl{"wave_length", ParamType::Float, {0.1, 0.0, 0.0}, 1e-6, 100.0, "The longest wave's length."},
        ParamDecl{"amplitude", ParamType::Float, {0.2, 0.0, 0.0}, 0.0, 1.0, "Wave height in wave lengths."},
        ParamDecl{"iterations", ParamType::Float, {5.0, 0.0, 0.0}, 0.0, 20.0, "How many waves, each finer."},
        ParamDecl{"phase", ParamType::Float, {0.0, 0.0, 0.0}, -100.0, 100.0, "Moves the waves (animation)."},
        toggleParam("log_part", false, "On: the fractal's part is the log estimate (power formulas)."),
        // Mandelbulber2 joins its water with whatever its DE function gives, the dIFS estimate too
        // (calculate_distance.cpp, 2.20).
        toggleParam("difs_part", false,
                    "On: the fractal's part is the dIFS estimate, the least shape distance along the orbit (dIFS "
                    "formulas); log_part and offset then play no part."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 k = normalize(axis);
    float s = sin(radians(angle)), co = cos(radians(angle));
    vec3 q = c - center;
    q = q * co + cross(k, q) * s + k * dot(k, q) * (1.0 - co);
    float g = q.z;
    if (g < 10.0 * wave_length * amplitude) {
        float waveX = 0.0, waveY = 0.0, pw = 1.0, p2 = 0.05;
        float x = q.x / wave_length, y = q.y / wave_length;
        for (int i = 1; i <= int(iterations); ++i) {
            float p3 = pw * p2, shift = phase / (float(i) / 2.697 + 1.0);
            float wx = sin(float(i) + 0.4 * waveX * p3 + sin(0.23 * y * p3 + shift * 0.134 * p3) + x * p3 + shift * p3) / pw;
            float wy =
                cos(float(i) + 0.4 * waveY * p3 + sin(x * p3 + shift * 0.0179 * p3) + 0.23 * y * p3 + shift * 0.023 * p3) /
                pw;
            waveX += wx;
            waveY += wy;
            p2 = p2 + (1.0 - p2 + 0.5 * sin(shift * 0.0323)) * 0.7;
            pw *= 1.872;
        }
        g += (waveX + waveY) * wave_length * amplitude;
    }
    float r = length(p.xyz);
    float f = log_part > 0.5 ? (r > 1.0 ? 0.5 * max(log(r) - surfaceLogR, 0.0) * r / abs(p.w) : 0.0)
                             : (r - offset) / abs(p.w);
    if (difs_part > 0.5) f = orbitDistance;
    float kb = max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
    float h = clamp(0.5 + 0.5 * sgn * (g - f) / kb, 0.0, 1.0);
    return sgn * (mix(sgn * g, sgn * f, h) - kb * h * (1.0 - h));
)";
    static double estimate(const P4& p, const vec3& c, Args a) {
        const double offset = a.f(0), intersect = a.f(1), blend = a.f(2);
        const vec3 center = a.v3(3), axis = a.v3(4);
        const double angle = a.f(5), waveLength = a.f(6), amplitude = a.f(7), iterations = a.f(8), phase = a.f(9);
        vec3 k = normalize(axis);
        double s = sin(glm::radians(angle)), co = cos(glm::radians(angle));
        vec3 q = c - center;
        q = q * co + glm::cross(k, q) * s + k * dot(k, q) * (1.0 - co);
        double g = q.z;
        if (g < 10.0 * waveLength * amplitude) g += waterHeight(q, waveLength, amplitude, iterations, phase);
        const double f = a.f(11) > 0.5 ? p.orbitDistance : fractalPart(p, offset, a.f(10));
        return joinParts(g, f, intersect, blend);
    }
};

}  // namespace fraktal::blocks
