#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Rotation about an axis through the origin (Rodrigues' formula). Rotations keep distances.
struct Rotate {
    static constexpr std::string_view id = "rotate";
    static constexpr std::string_view label = "Rotate";
    static constexpr std::string_view help = "Rotate about an axis through the origin.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"axis", ParamType::Vec3, {0.0, 1.0, 0.0}, -1.0, 1.0, "Rotation axis (normalised before use).", true},
        ParamDecl{"angle", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Angle in degrees."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 k = normalize(axis);
    float s = sin(radians(angle)), co = cos(radians(angle));
    p.xyz = p.xyz * co + cross(k, p.xyz) * s + k * dot(k, p.xyz) * (1.0 - co);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 axis = a.v3(0);
        const double angle = a.f(1);
        vec3 k = normalize(axis);
        double s = sin(glm::radians(angle)), co = cos(glm::radians(angle));
        p.xyz = p.xyz * co + glm::cross(k, p.xyz) * s + k * dot(k, p.xyz) * (1.0 - co);
    }
};

}  // namespace fraktal::blocks
