#pragma once
#include "core/plane/plane_block.hpp"

namespace fraktal::plane_blocks {

// Reflection across a line (seed 2.1.2: "reflect the plane across two lines"): points behind the
// line dot(z, n) = offset are mirrored onto its front. A mirror keeps distances (seed 3.2).
struct LineFold {
    static constexpr std::string_view id = "line_fold";
    static constexpr std::string_view label = "Line fold";
    static constexpr std::string_view help =
        "Mirror points behind the line dot(z, n) = offset onto its front; n points at the given angle.";
    static constexpr Category category = Category::Fold;
    static constexpr std::array params{
        ParamDecl{"angle", ParamType::Float, {0.0, 0.0, 0.0}, -360.0, 360.0, "Direction of the normal n, degrees from +x."},
        ParamDecl{"offset", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Signed distance of the line from the origin."},
    };

    static constexpr std::string_view glsl = R"(
    real2 n = real2(cos(radians(angle)), sin(radians(angle)));
    s.z -= real(2.0) * min(real(0.0), dot(s.z, n) - real(offset)) * n;
)";
    static void apply(PlaneState& s, const real2&, Args a) {
        const double angle = a.f(0), offset = a.f(1);
        real2 n = real2(std::cos(glm::radians(angle)), std::sin(glm::radians(angle)));
        s.z -= real(2.0) * std::min(real(0.0), glm::dot(s.z, n) - real(offset)) * n;
    }
};

}  // namespace fraktal::plane_blocks
