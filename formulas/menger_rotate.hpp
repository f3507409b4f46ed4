#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// One full Menger sponge iteration with a rotation (Knighty's Menger IFS, as in Syntopia part
// III and Mandelbulber2 menger_sponge): abs, sort so that x >= y >= z, rotate, scale s about the
// offset corner, and shift z back when it fell below the middle layer. Mirrors, rotations and
// shifts keep distances: the running derivative grows by |s| alone.
struct MengerRotate {
    static constexpr std::string_view id = "menger_rotate";
    static constexpr std::string_view label = "Menger with rotation";
    static constexpr std::string_view help =
        "Menger sponge iteration (abs, sort, rotate, scale about the corner); scale 3 and angle 0 is the sponge.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where it shifts z back below the middle layer";
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {3.0, 0.0, 0.0}, 1.0, 5.0, "Scale s per iteration."},
        ParamDecl{"offset", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 4.0, "Corner the scaling keeps fixed."},
        ParamDecl{"axis", ParamType::Vec3, {1.0, 0.0, 0.0}, -1.0, 1.0, "Rotation axis (normalised before use).", true},
        ParamDecl{"angle", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Rotation per iteration, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz = abs(p.xyz);
    float t = min(p.x - p.y, 0.0); p.x -= t; p.y += t;
    t = min(p.x - p.z, 0.0); p.x -= t; p.z += t;
    t = min(p.y - p.z, 0.0); p.y -= t; p.z += t;
    vec3 k = normalize(axis);
    float s = sin(radians(angle)), co = cos(radians(angle));
    p.xyz = p.xyz * co + cross(k, p.xyz) * s + k * dot(k, p.xyz) * (1.0 - co);
    p.xyz = p.xyz * scale - offset * (scale - 1.0);
    if (p.z < -0.5 * offset.z * (scale - 1.0)) p.z += offset.z * (scale - 1.0);
    p.w *= abs(scale);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), angle = a.f(3);
        const vec3 offset = a.v3(1), axis = a.v3(2);
        p.xyz = abs(p.xyz);
        double t = min(p.xyz.x - p.xyz.y, 0.0);
        p.xyz.x -= t;
        p.xyz.y += t;
        t = min(p.xyz.x - p.xyz.z, 0.0);
        p.xyz.x -= t;
        p.xyz.z += t;
        t = min(p.xyz.y - p.xyz.z, 0.0);
        p.xyz.y -= t;
        p.xyz.z += t;
        vec3 k = normalize(axis);
        double s = sin(glm::radians(angle)), co = cos(glm::radians(angle));
        p.xyz = p.xyz * co + glm::cross(k, p.xyz) * s + k * dot(k, p.xyz) * (1.0 - co);
        p.xyz = p.xyz * scale - offset * (scale - 1.0);
        if (p.xyz.z < -0.5 * offset.z * (scale - 1.0)) p.xyz.z += offset.z * (scale - 1.0);
        p.w *= abs(scale);
    }
};

}  // namespace fraktal::blocks
