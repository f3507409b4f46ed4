// The GL programs of the viewport passes. The passes that call the DE are compiled per formula
// structure; the others once. Each pass's dispatch lives in its own file (*_pass.cpp).
#pragma once

#include <string>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/gl/camera_uniforms.hpp"
#include "core/gl/formula_uniforms.hpp"
#include "core/gl/program.hpp"
#include "core/render/shading_params.hpp"
#include "core/render/shading_uniforms.hpp"

namespace fraktal::viewport {

// A program that evaluates the formula, with its uniform uploaders.
struct FormulaProgram {
    gl::Program program;
    gl::FormulaUniforms formula;
    gl::ShadingUniforms shading;
    // Binds the program and uploads the formula's values and the shading parameters.
    void use(const Formula& f, const ShadingParams& p) const;
};

struct ViewportPrograms {
    explicit ViewportPrograms(const Formula& formula);  // throws naming the node on a GLSL error
    std::string structure;
    // march resumes the rays; marchFromStart first starts them for a new view (reset or reprojected);
    // marchFromList marches on the rays either left on the march list.
    FormulaProgram march, marchFromStart, marchFromList, shade, cone;
    // accumulateAtRest raises the AA level; accumulateMoving finds the samples' positions instead.
    gl::Program accumulateAtRest, accumulateMoving, resolve, display;
    // Sets the shade and march lists' group counts from their entry counts (dispatchOverList).
    gl::Program listGroups;
    // The reprojection scatter's two passes (shaders/viewport_reproject.comp): claim, then write.
    gl::Program reprojectClaim, reprojectWrite;
};

// Sets viewport_common.glsl's camera uniforms on the bound program.
void setViewUniforms(GLuint program, const Camera& camera, int width, int height);
void setInt(GLuint program, const char* name, int value);
void setFloat(GLuint program, const char* name, float value);

}  // namespace fraktal::viewport
