#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's smooth Mandelbox folds (fractal_formulas.cpp MandelboxSmoothIteration): the box
// and sphere folds with each condition made a logistic step, 1 / (1 + e^(sharpness (b - a))) for
// a > b (common_math.h SmoothConditionAGreaterB). Per axis, x blends towards value - x as x passes
// +limit and towards -value - x as it passes -limit (both steps read x before either fold); then
// with r^2 = |v|^2, the inner scaling fixed^2 / min^2 blends in below min^2 and fixed^2 / r^2
// between min^2 and fixed^2: v k(r^2). The scale follows as its own node. The running
// derivative bounds the Jacobian at the point: the box part is diagonal (the largest |dx'/dx|,
// the steps' slopes included), the sphere part k I + 2 k'(r^2) v v^T stretches by k across and
// k + 2 r^2 k' along v. Each exponent is held within +-80 so that single precision gives the
// step's 0 or 1 rather than overflowing.
struct MandelboxSmoothFold {
    static constexpr std::string_view id = "mandelbox_smooth_fold";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
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
    vec3 x = p.xyz;
    vec3 above = 1.0 / (1.0 + exp(clamp(sharpness * (limit - x), -80.0, 80.0)));
    vec3 below = 1.0 / (1.0 + exp(clamp(sharpness * (x + limit), -80.0, 80.0)));
    vec3 y = x * (1.0 - above) + (value - x) * above;
    vec3 dy = 1.0 - 2.0 * above + (value - 2.0 * x) * sharpness * above * (1.0 - above);
    vec3 v = y * (1.0 - below) + (-value - y) * below;
    vec3 dv = dy * (1.0 - 2.0 * below) + (2.0 * y + value) * sharpness * below * (1.0 - below);
    float r2 = max(dot(v, v), 1e-12), mR2 = min_radius * min_radius, fR2 = fixed_radius * fixed_radius;
    float inner = 1.0 / (1.0 + exp(clamp(sharpness * (r2 - mR2), -80.0, 80.0)));
    float outer = 1.0 / (1.0 + exp(clamp(sharpness * (r2 - fR2), -80.0, 80.0)));
    float dInner = -sharpness * inner * (1.0 - inner), dOuter = -sharpness * outer * (1.0 - outer);
    float shell = (1.0 - inner) * outer, dShell = (1.0 - inner) * dOuter - dInner * outer;
    float A = 1.0 + (fR2 / mR2 - 1.0) * inner, dA = (fR2 / mR2 - 1.0) * dInner;
    float B = 1.0 + (fR2 / r2 - 1.0) * shell, dB = (fR2 / r2 - 1.0) * dShell - fR2 / (r2 * r2) * shell;
    float k = A * B, dk = dA * B + A * dB;
    p.xyz = v * k;
    p.w *= max(abs(dv.x), max(abs(dv.y), abs(dv.z))) * max(abs(k), abs(k + 2.0 * r2 * dk));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double limit = a.f(0), value = a.f(1), min_radius = a.f(2), fixed_radius = a.f(3), sharpness = a.f(4);
        vec3 x = p.xyz;
        vec3 above = 1.0 / (1.0 + glm::exp(glm::clamp(sharpness * (limit - x), -80.0, 80.0)));
        vec3 below = 1.0 / (1.0 + glm::exp(glm::clamp(sharpness * (x + limit), -80.0, 80.0)));
        vec3 y = x * (1.0 - above) + (value - x) * above;
        vec3 dy = 1.0 - 2.0 * above + (value - 2.0 * x) * sharpness * above * (1.0 - above);
        vec3 v = y * (1.0 - below) + (-value - y) * below;
        vec3 dv = dy * (1.0 - 2.0 * below) + (2.0 * y + value) * sharpness * below * (1.0 - below);
        double r2 = std::max(dot(v, v), 1e-12), mR2 = min_radius * min_radius, fR2 = fixed_radius * fixed_radius;
        double inner = 1.0 / (1.0 + std::exp(std::clamp(sharpness * (r2 - mR2), -80.0, 80.0)));
        double outer = 1.0 / (1.0 + std::exp(std::clamp(sharpness * (r2 - fR2), -80.0, 80.0)));
        double dInner = -sharpness * inner * (1.0 - inner), dOuter = -sharpness * outer * (1.0 - outer);
        double shell = (1.0 - inner) * outer, dShell = (1.0 - inner) * dOuter - dInner * outer;
        double A = 1.0 + (fR2 / mR2 - 1.0) * inner, dA = (fR2 / mR2 - 1.0) * dInner;
        double B = 1.0 + (fR2 / r2 - 1.0) * shell, dB = (fR2 / r2 - 1.0) * dShell - fR2 / (r2 * r2) * shell;
        double k = A * B, dk = dA * B + A * dB;
        p.xyz = v * k;
        p.w *= max(abs(dv.x), max(abs(dv.y), abs(dv.z))) * max(abs(k), abs(k + 2.0 * r2 * dk));
    }
};

}  // namespace fraktal::blocks
