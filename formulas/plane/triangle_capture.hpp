#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// A triangle test that decides membership (seed 2.1.2): a point inside the given equilateral
// triangle (pointing up) is part of the fractal and stops iterating. The Koch snowflake uses it
// for its starting triangle and for the bump on each segment's middle third.
struct TriangleCapture {
    static constexpr std::string_view id = "triangle_capture";
    static constexpr std::string_view label = "Triangle capture";
    static constexpr std::string_view help = "Inside this triangle (pointing up): part of the fractal, stop.";
    static constexpr Category category = Category::Fold;
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.001, 100.0, "Circumradius of the triangle."},
        ParamDecl{"center_x", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Centroid, x."},
        ParamDecl{"center_y", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Centroid, y."},
    };

    static constexpr std::string_view glsl = R"(
    if (planeSdTriangle(s.z - real2(center_x, center_y), real(radius)) <= 0.0) s.captured = true;
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double radius = a.f(0), center_x = a.f(1), center_y = a.f(2);
        if (planeSdTriangle(s.z - real2(center_x, center_y), real(radius)) <= 0.0) s.captured = true;
    }
};

}  // namespace fraktal::plane_blocks
