// The GL programs of the viewport passes. The passes that call the DE are compiled per formula
// structure; the others once. Each pass's dispatch lives in its own file (*_pass.cpp).
#pragma once

#include <string>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/gl/camera_uniforms.hpp"
#include "core/gl/formula_uniforms.hpp"
#include "core/gl/program.hpp"
#include "core/render/shading_uniforms.hpp"
#include "core/shading_params.hpp"
#include "core/viewport/pass_images.hpp"

namespace fraktal::viewport {

// The locations of the uniforms the viewport passes set, looked up once when a program is built,
// so that a frame sets values without looking up names. A pass's program has the ones its
// shaders use; the others are -1, which GL ignores.
struct PassUniforms {
    gl::CameraLocations camera;
    gl::CameraLocations newCamera;  // the reprojection's current camera (the points' is `camera`)
    gl::LensLocations lens;         // shaders/lens.glsl
    GLint size = -1, pixelAngle = -1, newSize = -1, block = -1;
    GLint stepsPerFrame = -1, maxSteps = -1, atRest = -1, maxCarryFrames = -1, coarseHits = -1, deferAfter = -1,
          resetAll = -1;
    GLint sliceCount = -1, sliceIndex = -1, generation = -1;
    GLint coneTile = -1, coneSteps = -1;
    GLint maxSamples = -1, initialOmega = -1, radius = -1;
    GLint exposure = -1, flipY = -1;
    PassUniforms() = default;
    explicit PassUniforms(GLuint program);
};

// A program with its uniforms' locations and its images' units.
struct Pass {
    gl::Program program;
    PassUniforms uniforms;
    PassImages images;
    GLuint id() const { return program.id(); }
    // Binds the program and its images of `state`.
    void use(const MarchState& state) const;
};

// A program that evaluates the formula, with its uniform uploaders.
struct FormulaProgram {
    gl::Program program;
    PassUniforms uniforms;
    PassImages images;
    gl::FormulaUniforms formula;
    gl::ShadingUniforms shading;
    // Binds the program and its images of `state`, and uploads the formula's values and the
    // shading parameters.
    void use(const MarchState& state, const Formula& f, const ShadingParams& p) const;
};

struct ViewportPrograms {
    explicit ViewportPrograms(const Formula& formula);  // throws naming the node on a GLSL error
    std::string structure;
    // march resumes the rays; marchFromStart first starts them for a new view (reset or reprojected);
    // marchFromList marches on the rays either left on the march list. march also starts the rays
    // of an older view in the slice it marches (a sliced reset starts none over the whole view).
    FormulaProgram march, marchFromStart, marchFromList, shade, cone;
    // accumulateAtRest raises the AA level; accumulateMoving finds the samples' positions instead.
    Pass accumulateAtRest, accumulateMoving, resolve, display;
    // Sets the shade and march lists' group counts from their entry counts (dispatchOverList).
    gl::Program listGroups;
    // The reprojection scatter's two passes (shaders/viewport_reproject.comp): claim, then write.
    Pass reprojectClaim, reprojectWrite;
    Pass reprojectBlockClaim, reprojectBlockWrite;  // onto a grid several times smaller (reprojectBlock)
    // Every program above, for the checks that cover every program fraktal links.
    std::vector<const gl::Program*> all() const;
};

// Sets viewport_common.glsl's camera uniforms on the bound program whose locations `at` holds.
void setViewUniforms(const PassUniforms& at, const Camera& camera, int width, int height, const ThinLens& lens = {});

}  // namespace fraktal::viewport
