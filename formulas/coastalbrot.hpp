#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's coastalbrot (fractal_formulas.cpp CoastalbrotIteration): each coordinate
// through sin(sin(sin(pi / 3 + pi x))), the whole scaled by r^8.7. The sines keep each coordinate
// within [-0.85, 0.85], so the orbit's growth is the power's; the running derivative is
// Mandelbulber2's 7.7 r^7.7 (the sines' stretch, up to pi per axis, is estimated, not bounded:
// `fraktal check` measures the step factor).
struct Coastalbrot {
    static constexpr std::string_view id = "coastalbrot";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Coastalbrot";
    static constexpr std::string_view help = "Each coordinate through three nested sines, scaled by r^8.7.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 8.7};
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    float grow = pow(r, 7.7);
    p.w = grow * p.w * 7.7;
    grow *= r;
    p.xyz = sin(sin(sin(1.0471975511966 + p.xyz * 3.14159265358979))) * grow;
)";
    static void apply(P4& p, const vec3&, Args) {
        double r = length(p.xyz);
        double grow = std::pow(r, 7.7);
        p.w = grow * p.w * 7.7;
        grow *= r;
        p.xyz = glm::sin(glm::sin(glm::sin(1.0471975511966 + p.xyz * 3.14159265358979))) * grow;
    }
};

}  // namespace fraktal::blocks
