// CPU-side vector types that mirror GLSL, so a block's CPU code reads line for line like its GLSL.
#pragma once

#include <glm/glm.hpp>

namespace fraktal {

using vec2 = glm::dvec2;
using vec3 = glm::dvec3;
using vec4 = glm::dvec4;
using mat3 = glm::dmat3;

// The iteration state, as in PySpace: xyz is the point, w the running scale / derivative.
// GLSL keeps it in a vec4 p; on the CPU the members are named so that `p.xyz` and `p.w`
// read the same in both languages.
struct P4 {
    vec3 xyz{0.0};
    double w = 1.0;
    // The product of the degrees of the power steps applied so far (BlockDesc::degreeAt; GLSL:
    // `degree`, a local of formulaEval that the estimator receives): escape-time potential
    // estimates divide log r by it.
    double degree = 1.0;
};

using glm::abs;
using glm::clamp;
using glm::cos;
using glm::dot;
using glm::length;
using glm::max;
using glm::min;
using glm::normalize;
using glm::sin;

}  // namespace fraktal
