#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Knighty's kaleidoscopic IFS with a per-iteration rotation (Syntopia, "Distance estimated 3D
// fractals part III"): abs and the two golden-ratio mirrors n1 = (-phi, phi-1, 1), n2 = (1, -phi, phi+1), twice
// (icosahedral/dodecahedral group), then a rotation about an axis (Rodrigues), then a scale s about the offset vertex:
// v -> s v - offset (s - 1). Mirrors and rotations keep distances, so the running derivative grows by |s| alone (a
// similarity).
struct KifsIcosahedral {
    static constexpr std::string_view id = "kifs_icosahedral";
    static constexpr std::string_view label = "KIFS icosahedral";
    static constexpr std::string_view help =
        "Kaleidoscopic IFS: icosahedral mirrors, rotate, scale about the offset vertex.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {2.0, 0.0, 0.0}, 1.0, 4.0, "Scale s per iteration."},
        ParamDecl{"offset", ParamType::Vec3, {0.850651, 0.525731, 0.0}, -4.0, 4.0, "Vertex the scaling keeps fixed."},
        ParamDecl{"axis", ParamType::Vec3, {0.0, 0.0, 1.0}, -1.0, 1.0, "Rotation axis (normalised before use).", true},
        ParamDecl{"angle", ParamType::Float, {0.0, 0.0, 0.0}, -180.0, 180.0, "Rotation per iteration, degrees."},
    };

    static constexpr std::string_view glsl = R"(
    const float phi = 1.61803398875;
    vec3 n1 = normalize(vec3(-phi, phi - 1.0, 1.0)), n2 = normalize(vec3(1.0, -phi, phi + 1.0));
    for (int j = 0; j < 2; ++j) {
        p.xyz = abs(p.xyz);
        p.xyz -= 2.0 * max(dot(p.xyz, n1), 0.0) * n1;
        p.xyz -= 2.0 * max(dot(p.xyz, n2), 0.0) * n2;
    }
    p.xyz = abs(p.xyz);
    vec3 k = normalize(axis);
    float s = sin(radians(angle)), co = cos(radians(angle));
    p.xyz = p.xyz * co + cross(k, p.xyz) * s + k * dot(k, p.xyz) * (1.0 - co);
    p.xyz = p.xyz * scale - offset * (scale - 1.0);
    p.w *= abs(scale);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), angle = a.f(3);
        const vec3 offset = a.v3(1), axis = a.v3(2);
        const double phi = 1.61803398875;
        vec3 n1 = normalize(vec3(-phi, phi - 1.0, 1.0)), n2 = normalize(vec3(1.0, -phi, phi + 1.0));
        for (int j = 0; j < 2; ++j) {
            p.xyz = abs(p.xyz);
            p.xyz -= 2.0 * max(dot(p.xyz, n1), 0.0) * n1;
            p.xyz -= 2.0 * max(dot(p.xyz, n2), 0.0) * n2;
        }
        p.xyz = abs(p.xyz);
        vec3 k = normalize(axis);
        double s = sin(glm::radians(angle)), co = cos(glm::radians(angle));
        p.xyz = p.xyz * co + glm::cross(k, p.xyz) * s + k * dot(k, p.xyz) * (1.0 - co);
        p.xyz = p.xyz * scale - offset * (scale - 1.0);
        p.w *= abs(scale);
    }
};

}  // namespace fraktal::blocks
