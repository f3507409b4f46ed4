#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's smooth Mandelbox folds (fractal_formulas.cpp MandelboxSmoothIteration): the box
// and sphere folds with each condition made a logistic step, 1 / (1 + e^(sharpness (b - a))) for
// a > b (common_math.h SmoothConditionAGreaterB). Per axis, x blends towards value - x as x passes
// +limit and towards -value - x as it passes -limit (both steps read x before either fold); then
// with r^2 = |v|^2, the inner scaling fixed^2 / min^2 blends in below min^2 and fixed^2 / r^2
// between min^2 and fixed^2. The scale follows as its own node. The blends can stretch a little
// more than the sharp folds' bounds, so the running derivative takes the sphere folds' factors
// and `fraktal check` measures the step factor. Each exponent is held within +-80 so that single
// precision gives the step's 0 or 1 rather than overflowing.
struct MandelboxSmoothFold {
    static constexpr std::string_view id = "mandelbox_smooth_fold";
    static constexpr std::string_view label = "Smooth Mandelbox folds";
    static constexpr std::string_view help =
        "The Mandelbox's box and sphere folds with logistic steps in place of their conditions (Mandelbulber2's "
        "mandelbox_smooth).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 4.0, "Box folding limit."},
        ParamDecl{"value", ParamType::Float, {2.0, 0.0, 0.0}, 0.0, 8.0, "Box folding value (2 x limit folds at it)."},
        ParamDecl{"min_radius", ParamType::Float, {0.5, 0.0, 0.0}, 0.001, 4.0, "Inner radius of the sphere fold."},
        ParamDecl{"fixed_radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.001, 4.0, "Fixed radius of the sphere fold."},
        ParamDecl{"sharpness", ParamType::Float, {3.0, 0.0, 0.0}, 0.01, 100.0, "Steepness of the logistic steps."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    vec3 above = 1.0 / (1.0 + exp(clamp(sharpness * (limit - v), -80.0, 80.0)));
    vec3 below = 1.0 / (1.0 + exp(clamp(sharpness * (v + limit), -80.0, 80.0)));
    v = v * (1.0 - above) + (value - v) * above;
    v = v * (1.0 - below) + (-value - v) * below;
    float r2 = dot(v, v), mR2 = min_radius * min_radius, fR2 = fixed_radius * fixed_radius;
    float inner = 1.0 / (1.0 + exp(clamp(sharpness * (r2 - mR2), -80.0, 80.0)));
    float shell = (1.0 - inner) / (1.0 + exp(clamp(sharpness * (r2 - fR2), -80.0, 80.0)));
    float k = (1.0 - inner + fR2 / mR2 * inner) * (1.0 - shell + fR2 / max(r2, 1e-30) * shell);
    p.xyz = v * k;
    p.w *= k;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double limit = a.f(0), value = a.f(1), min_radius = a.f(2), fixed_radius = a.f(3), sharpness = a.f(4);
        vec3 v = p.xyz;
        vec3 above = 1.0 / (1.0 + glm::exp(glm::clamp(sharpness * (limit - v), -80.0, 80.0)));
        vec3 below = 1.0 / (1.0 + glm::exp(glm::clamp(sharpness * (v + limit), -80.0, 80.0)));
        v = v * (1.0 - above) + (value - v) * above;
        v = v * (1.0 - below) + (-value - v) * below;
        double r2 = dot(v, v), mR2 = min_radius * min_radius, fR2 = fixed_radius * fixed_radius;
        double inner = 1.0 / (1.0 + std::exp(std::clamp(sharpness * (r2 - mR2), -80.0, 80.0)));
        double shell = (1.0 - inner) / (1.0 + std::exp(std::clamp(sharpness * (r2 - fR2), -80.0, 80.0)));
        double k = (1.0 - inner + fR2 / mR2 * inner) * (1.0 - shell + fR2 / std::max(r2, 1e-30) * shell);
        p.xyz = v * k;
        p.w *= k;
    }
};

}  // namespace fraktal::blocks
