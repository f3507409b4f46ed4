#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Knighty's kaleidoscopic IFS with a per-iteration rotation (Syntopia, "Distance estimated 3D
// fractals part III"): abs, then mirrors across x=y, x=z and y=z (octahedral group), then a rotation about an axis
// (Rodrigues), then a scale s about the offset vertex: v -> s v - offset (s - 1). Mirrors and rotations keep distances,
// so the running derivative grows by |s| alone (a similarity).
struct KifsOctahedral {
    static constexpr std::string_view id = "kifs_octahedral";
    static constexpr std::string_view label = "KIFS octahedral";
    static constexpr std::string_view help =
        "Kaleidoscopic IFS: octahedral mirrors, rotate, scale about the offset vertex.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {2.0, 0.0, 0.0}, 1.0, 4.0, "Scale s per iteration."},
        ParamDecl{"offset", ParamType::Vec3, {1.0, 0.0, 0.0}, -4.0, 4.0, "Vertex the scaling keeps fixed."},
        ParamDecl{"axis", ParamType::Vec3, {0.0, 0.0, 1.0}, -1.0, 1.0, "Rotation axis (normalised before use).", true},
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
        p.w *= abs(scale);
    }
};

}  // namespace fraktal::blocks
