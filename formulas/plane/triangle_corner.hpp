#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// The seed's Sierpinski step (2.1.1): find which of the three corner triangles (half size, one
// at each vertex of the reference triangle) holds the point; if none, it is outside; else map that
// corner onto the whole (a scale by 2 about its vertex) and repeat. The reference triangle points
// up, centroid at the origin, circumradius `radius`: vertices (0, R), (-R sqrt3/2, -R/2),
// (R sqrt3/2, -R/2). A corner's centroid is half its vertex.
struct TriangleCorner {
    static constexpr std::string_view id = "triangle_corner";
    static constexpr std::string_view label = "Triangle corner test";
    static constexpr std::string_view help =
        "Sierpinski step: map the corner triangle holding z onto the whole triangle; none: outside.";
    static constexpr Category category = Category::Fold;
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.001, 100.0, "Circumradius of the reference triangle."},
    };

    static constexpr std::string_view glsl = R"(
    real R = real(radius);
    real2 vertices[3] = real2[3](real2(0.0, R), real2(-R * sqrt(real(3.0)) * 0.5, -R * 0.5),
                                 real2(R * sqrt(real(3.0)) * 0.5, -R * 0.5));
    for (int k = 0; k < 3; ++k) {
        if (planeSdTriangle(s.z - vertices[k] * 0.5, R * 0.5) <= 0.0) {
            s.z = real(2.0) * s.z - vertices[k];
            s.dz *= real(2.0);
            return;
        }
    }
    s.escaped = true;
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double radius = a.f(0);
        real R = real(radius);
        real2 vertices[3] = {real2(0.0, R), real2(-R * std::sqrt(real(3.0)) * 0.5, -R * 0.5),
                             real2(R * std::sqrt(real(3.0)) * 0.5, -R * 0.5)};
        for (int k = 0; k < 3; ++k) {
            if (planeSdTriangle(s.z - vertices[k] * 0.5, R * 0.5) <= 0.0) {
                s.z = real(2.0) * s.z - vertices[k];
                s.dz *= real(2.0);
                return;
            }
        }
        s.escaped = true;
    }
};

}  // namespace fraktal::plane_blocks
