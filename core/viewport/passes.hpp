// The viewport's GL passes, one file each (seed chapter 4). All run on the current context with
// the march state's lists and the counters bound (MarchState::bindLists); each binds its own
// images (pass_images.hpp).
#pragma once

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/shading_params.hpp"
#include "core/viewport/frame_logic.hpp"
#include "core/viewport/march_state.hpp"
#include "core/viewport/viewport_options.hpp"
#include "core/viewport/viewport_programs.hpp"

namespace fraktal::viewport {

// What every pass of one frame reads.
struct FrameContext {
    const Formula& formula;
    const Camera& camera;
    const ShadingParams& shading;
    const ViewportOptions& options;
    int maxSteps;
    bool atRest;    // FrameAction::Continue: the AA level may rise
    ThinLens lens;  // the AA samples' lens (sample 0, the one reprojection carries, is a pinhole ray)
    // The frame's slice of the view (sliced refinement, Viewport::render): the march advances the
    // tiles whose number modulo sliceCount is sliceIndex (dispatchOverSlice). 1: the whole view.
    int sliceCount = 1;
    int sliceIndex = 0;
};

// The old pixels per side that one invocation of the reprojection scatters: the whole ratio of the
// grids, at most kMaxReprojectBlock, where motion moves onto a grid several times smaller (1 for
// grids of about the same size). Pure, for the unit test.
constexpr int kMaxReprojectBlock = 4;
int reprojectBlock(int oldWidth, int oldHeight, int newWidth, int newHeight);

// Reprojection (reproject_pass.cpp): scatters the previous frame's points (`from`'s images, seen
// from the previous camera) into the reprojection target of `to` (MarchState::reprojDepth /
// reprojColor / reprojCarried) for the current one. `from` and `to` are the same state unless
// the grid's size changed between the frames (dynamic resolution).
void runReprojectPass(const ViewportPrograms& p, const MarchState& from, const MarchState& to, const Camera& previous,
                      const Camera& current);

void runConePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c);
// Advances the rays. On a new view (action Reset or Reproject) it first starts them: from the
// camera on a reset, else from the reprojection. With a slice (c.sliceCount > 1; a continued view
// or a reset, never a reprojected one, whose starts are verified in their first step) only the
// slice's rays step: a sliced reset starts no ray over the whole view (the march starts each ray
// of an older view when its slice comes, MarchState::generation), and the march is dispatched over the slice's tiles
// alone, so that it and the shading (the shade list holds what it finished) cost about a sliceCount-th of the whole
// view's. On a reprojected frame, rays it leaves marching with steps left (ViewportOptions::deferAfterSteps) go on the
// march list, which runMarchListPass marches on.
void runMarchPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action);
void runMarchListPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action);
void runShadePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c);
void runAccumulatePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c);
void runResolvePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c);

// Exposure and the sRGB curve, from the scene-linear image into the bound framebuffer.
void runDisplayPass(const ViewportPrograms& p, const MarchState& s, float exposure, bool flipY, GLuint vertexArray);

// Runs a 2D pass over the view, or with a slice (c.sliceCount > 1) over the slice's tiles alone:
// the view's workgroups numbered row by row, those whose number modulo sliceCount is sliceIndex
// (the shader finds its tile with slicePixel, shaders/viewport_common.glsl, from u_sliceCount and
// u_sliceIndex, which this sets on the bound program).
void dispatchOverSlice(GLuint program, const PassUniforms& at, const MarchState& s, const FrameContext& c);

// Between passes that write images and passes that read them.
inline void imageBarrier() {
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT |
                    GL_FRAMEBUFFER_BARRIER_BIT);
}

// Runs a program once per entry of a pixel list (MarchState::shadeList or marchList): sets the
// lists' group counts (p.listGroups), then an indirect dispatch of as many groups, then an image
// barrier.
inline void dispatchOverList(const ViewportPrograms& p, GLuint program, GLuint list) {
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    glUseProgram(p.listGroups.id());
    glDispatchCompute(1, 1, 1);
    glUseProgram(program);
    glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, list);
    glDispatchComputeIndirect(0);
    glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
    imageBarrier();
}

}  // namespace fraktal::viewport
