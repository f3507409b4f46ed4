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
        ParamDecl{"height", ParamType::Float, {-1.0, 0.0, 0.0}, -10.0, 10.0, "Plane offset along the normal."},
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
        double k = std::max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
        double h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
        return sgn * (glm::mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
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
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, 0.0}, -10.0, 10.0, "Sphere centre."},
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "Sphere radius."},
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
        double k = std::max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
        double h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
        return sgn * (glm::mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
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
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, 0.0}, -10.0, 10.0, "Box centre."},
        ParamDecl{"size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.001, 10.0, "Half-size of the box."},
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
        double k = std::max(blend, 1e-6), sgn = intersect >= 0.5 ? -1.0 : 1.0;
        double h = clamp(0.5 + 0.5 * sgn * (g - f) / k, 0.0, 1.0);
        return sgn * (glm::mix(sgn * g, sgn * f, h) - k * h * (1.0 - h));
    }
};

}  // namespace fraktal::blocks
