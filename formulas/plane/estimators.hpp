// Closing estimators of 2D formulas: a distance (a lower bound where possible) from the final
// state, over the running scale or derivative, for distance-estimate shading; and the rule that
// decides membership (core/plane/plane_block.hpp, PlaneMembership).
#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// Escape-time distance: 0.5 |z| log|z| / |dz| (Milnor's estimate halved: the Koebe 1/4 theorem
// bounds the true distance between a quarter and twice G/|G'|, so this stays conservative).
struct EscapeEstimator {
    static constexpr std::string_view id = "escape";
    static constexpr std::string_view label = "Escape time";
    static constexpr std::string_view help = "Inside unless the orbit passed the bailout; distance 0.5 |z| log|z| / |dz|.";
    static constexpr Category category = Category::Estimator;
    static constexpr PlaneMembership membership = PlaneMembership::NotEscaped;
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float r = float(length(s.z));
    return 0.5 * r * log(r) / float(s.dz);
)";
    static double estimate(const PlaneState& s, const real2&, Args) {
        double r = glm::length(s.z);
        return 0.5 * r * std::log(r) / s.dz;
    }
};

// Sierpinski closing test: inside when no corner test rejected the point and it lies in the
// reference triangle (at depth 0 that is the whole test; after a corner step it always does). For a point a corner test rejected, the fractal lies in the three corners, so the
// distance is at least the larger of the distance to the triangle and the depth inside the
// removed middle triangle (the inverted one of half the circumradius).
struct TriangleEstimator {
    static constexpr std::string_view id = "triangle";
    static constexpr std::string_view label = "Triangle";
    static constexpr std::string_view help = "Distance to the reference triangle (or to its kept corners), over the running scale.";
    static constexpr Category category = Category::Estimator;
    static constexpr PlaneMembership membership = PlaneMembership::Region;
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.001, 100.0, "Circumradius of the reference triangle."},
    };

    static constexpr std::string_view glsl = R"(
    real d = planeSdTriangle(s.z, real(radius));
    if (s.escaped) d = max(d, -planeSdTriangle(-s.z, real(radius) * 0.5));
    return float(d / s.dz);
)";
    static double estimate(const PlaneState& s, const real2&, Args a) {
        const double radius = a.f(0);
        real d = planeSdTriangle(s.z, real(radius));
        if (s.escaped) d = std::max(d, -planeSdTriangle(-s.z, real(radius) * 0.5));
        return double(d / s.dz);
    }
};

// Koch closing test (seed 2.1.2): membership is decided by the triangle captures alone. Distance:
// the rest of the curve over the current segment (on the x axis, half-length a) lies within
// `height` of it, so the distance to the segment minus that height bounds the distance to it.
struct SegmentEstimator {
    static constexpr std::string_view id = "segment";
    static constexpr std::string_view label = "Segment (captured)";
    static constexpr std::string_view help =
        "Inside only where a triangle test captured the point; distance to the segment's hull, over the running scale.";
    static constexpr Category category = Category::Estimator;
    static constexpr PlaneMembership membership = PlaneMembership::Captured;
    static constexpr std::array params{
        ParamDecl{"half_length", ParamType::Float, {0.8660254037844386, 0.0, 0.0}, 0.001, 100.0, "Half-length a of the segment."},
        ParamDecl{"height", ParamType::Float, {0.5, 0.0, 0.0}, 0.0, 100.0, "How far the curve rises above the segment."},
    };

    static constexpr std::string_view glsl = R"(
    real2 q = s.z - real2(clamp(s.z.x, -real(half_length), real(half_length)), 0.0);
    return float((length(q) - real(height)) / s.dz);
)";
    static double estimate(const PlaneState& s, const real2&, Args a) {
        const double half_length = a.f(0), height = a.f(1);
        real2 q = s.z - real2(std::clamp(s.z.x, -real(half_length), real(half_length)), 0.0);
        return double((glm::length(q) - real(height)) / s.dz);
    }
};

}  // namespace fraktal::plane_blocks
