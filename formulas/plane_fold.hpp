#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Reflect the half-space behind a plane onto its front (PySpace FoldPlane): a mirror keeps the
// nearest point on one side, so distances are preserved (seed 3.2).
struct PlaneFold {
    static constexpr std::string_view id = "plane_fold";
    static constexpr std::string_view label = "Plane fold";
    static constexpr std::string_view help =
        "Mirror points behind the plane dot(p, normal) = offset onto its front side.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"normal", ParamType::Vec3, {0.0, 0.0, 1.0}, -1.0, 1.0, "Plane normal (normalised before use).", true},
        ParamDecl{
            "offset", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Signed distance of the plane from the origin."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 n = normalize(normal);
    p.xyz -= 2.0 * min(0.0, dot(p.xyz, n) - offset) * n;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 normal = a.v3(0);
        const double offset = a.f(1);
        vec3 n = normalize(normal);
        p.xyz -= 2.0 * min(0.0, dot(p.xyz, n) - offset) * n;
    }
};

}  // namespace fraktal::blocks
