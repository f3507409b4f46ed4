#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// Rotation about a centre. Rotations keep distances.
struct Rotate {
    static constexpr std::string_view id = "rotate";
    static constexpr std::string_view label = "Rotate";
    static constexpr std::string_view help = "Rotate about a centre by an angle (counter-clockwise).";
    static constexpr Category category = Category::Transform;
    static constexpr std::array params{
        ParamDecl{"angle", ParamType::Float, {0.0, 0.0, 0.0}, -360.0, 360.0, "Angle in degrees."},
        ParamDecl{"center_x", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Centre of rotation, x."},
        ParamDecl{"center_y", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Centre of rotation, y."},
    };

    static constexpr std::string_view glsl = R"(
    real co = real(cos(radians(angle))), si = real(sin(radians(angle)));
    real2 o = real2(center_x, center_y);
    real2 q = s.z - o;
    s.z = o + real2(co * q.x - si * q.y, si * q.x + co * q.y);
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double angle = a.f(0), center_x = a.f(1), center_y = a.f(2);
        real co = std::cos(glm::radians(angle)), si = std::sin(glm::radians(angle));
        real2 o = real2(center_x, center_y);
        real2 q = s.z - o;
        s.z = o + real2(co * q.x - si * q.y, si * q.x + co * q.y);
    }
};

}  // namespace fraktal::plane_blocks
