#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Turns of the 4D point (xyz, P4::pointW; formulas/four_d.hpp) in the planes xy, yz, xz, then xw,
// yw, zw, in that order, each (u, v) -> (u cos t + v sin t, -u sin t + v cos t), as Mandelbulber2's
// 4D formulas turn it (2.20's Abox4dIteration, option R: rotation44a and rotation44b in degrees,
// fractal_formulas.cpp). Rotations keep distances: the running derivative is unchanged.
struct Rotate4d {
    static constexpr std::string_view id = "rotate4d";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Rotate 4D";
    static constexpr std::string_view help =
        "Turn the 4D point in the planes xy, yz and xz, then xw, yw and zw, in that order (degrees; Mandelbulber2's "
        "4D turn).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"angles", ParamType::Vec3, {0.0, 0.0, 0.0}, -180.0, 180.0, "Turns in the xy, yz and xz planes."},
        ParamDecl{"angles_w", ParamType::Vec3, {0.0, 0.0, 0.0}, -180.0, 180.0, "Turns in the xw, yw and zw planes."},
    };

    static constexpr std::string_view glsl = R"(
    vec4 v = vec4(p.xyz, pointW);
    const ivec2 planes[6] = ivec2[6](ivec2(0, 1), ivec2(1, 2), ivec2(0, 2), ivec2(0, 3), ivec2(1, 3), ivec2(2, 3));
    for (int k = 0; k < 6; ++k) {
        float t = radians(k < 3 ? angles[k] : angles_w[k - 3]);
        float a = v[planes[k].x], b = v[planes[k].y];
        v[planes[k].x] = a * cos(t) + b * sin(t);
        v[planes[k].y] = -a * sin(t) + b * cos(t);
    }
    p.xyz = v.xyz;
    pointW = v.w;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 angles = a.v3(0), anglesW = a.v3(1);
        vec4 v(p.xyz, p.pointW);
        const int planes[6][2] = {{0, 1}, {1, 2}, {0, 2}, {0, 3}, {1, 3}, {2, 3}};
        for (int k = 0; k < 6; ++k) {
            const double t = glm::radians(k < 3 ? angles[k] : anglesW[k - 3]);
            const double x = v[planes[k][0]], y = v[planes[k][1]];
            v[planes[k][0]] = x * std::cos(t) + y * std::sin(t);
            v[planes[k][1]] = -x * std::sin(t) + y * std::cos(t);
        }
        p.xyz = vec3(v);
        p.pointW = v.w;
    }
};

}  // namespace fraktal::blocks
