// GLSL generation for 2D formulas, with the same per-node #line markers as the 3D generator
// (core/glsl_gen.hpp) so that a compile error names the node. The result plugs into
// assembleShader() and gl::compileCompute() unchanged.
#pragma once

#include <string>

#include "core/glsl_gen.hpp"
#include "core/plane/plane_formula.hpp"

namespace fraktal {

// Defines planeEval(real2 pos, out int iterations, out float smoothIterations, out bool inside).
GeneratedFormula generatePlaneGLSL(const PlaneFormula& f);

// Uniform name of parameter `param` of node k (start nodes first, then loop nodes, then the
// estimator), shared by the generator and the uploader.
std::string planeUniformName(int nodeIndex, std::string_view param);

// The define that selects double precision in shaders/plane_formula.glsl.
inline constexpr std::string_view kPlaneFp64Define = "#define FRAKTAL_PLANE_FP64 1\n";

}  // namespace fraktal
