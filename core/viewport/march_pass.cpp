// Progressive marching, and on a new view the rays' starts (shaders/viewport_march.comp with
// shaders/viewport_start.glsl); then the rays left on the march list.
#include <algorithm>
#include <climits>

#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

namespace {

// The steps the full-screen pass takes before a ray goes on the march list; 0: it takes them all.
int stepsBeforeList(const FrameContext& c, FrameAction action) {
    return action == FrameAction::Reproject ? std::max(c.options.deferAfterSteps, 0) : 0;
}

// The uniforms every variant of viewport_march.comp reads.
void setMarchUniforms(const FormulaProgram& pass, const MarchState& s, const FrameContext& c, FrameAction action) {
    const PassUniforms& at = pass.uniforms;
    pass.use(s, c.formula, c.shading);
    setViewUniforms(at, c.camera, s.width(), s.height(), c.lens);
    glUniform1i(at.stepsPerFrame, c.options.stepsPerFrame);
    glUniform1i(at.maxSteps, c.maxSteps);
    glUniform1i(at.atRest, c.atRest ? 1 : 0);
    glUniform1i(at.maxCarryFrames, c.options.maxCarryFrames);  // keepsCarriedColour
    glUniform1i(at.coarseHits, c.options.coarseHits ? 1 : 0);
    const int deferAfter = stepsBeforeList(c, action);
    glUniform1i(at.deferAfter, deferAfter > 0 ? deferAfter : INT_MAX);
    glUniform1i(at.sliceCount, std::max(c.sliceCount, 1));
    glUniform1i(at.sliceIndex, c.sliceIndex);
    glUniform1i(at.generation, s.generation);
}

}  // namespace

void runMarchPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action) {
    const bool newView = action != FrameAction::Continue;
    s.clearShadeList();
    s.clearMarchList();
    // A sliced new view (a reset) starts no ray here: the march below starts the slice's, as each
    // later frame does its slice's rays of an older view (viewport_march.comp).
    if (newView && c.sliceCount <= 1) {
        const FormulaProgram& pass = p.marchFromStart;
        setMarchUniforms(pass, s, c, action);
        glUniform1i(pass.uniforms.resetAll, action == FrameAction::Reset ? 1 : 0);
        glUniform1i(pass.uniforms.coneTile, c.options.coneTile);
        glBindTextureUnit(1, s.reprojColor);
        glBindTextureUnit(2, s.reprojCarried);
        // MarchState::accum needs no reset: every pixel starts a new sample 0, whose colour
        // replaces the sum (viewport_accumulate.comp).
        gl::dispatchOver(pass.program.id(), s.width(), s.height());
        imageBarrier();
        return;
    }
    setMarchUniforms(p.march, s, c, action);
    dispatchOverSlice(p.march.program.id(), p.march.uniforms, s, c);
    imageBarrier();
}

void dispatchOverSlice(GLuint program, const PassUniforms& at, const MarchState& s, const FrameContext& c) {
    const int slices = std::max(c.sliceCount, 1);
    glUniform1i(at.sliceCount, slices);
    glUniform1i(at.sliceIndex, slices > 1 ? c.sliceIndex : 0);
    GLint group[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, group);
    const int tiles = ((s.width() + group[0] - 1) / group[0]) * ((s.height() + group[1] - 1) / group[1]);
    const int inSlice = slices > 1 ? std::max(tiles - c.sliceIndex + slices - 1, 0) / slices : tiles;
    // In rows of at most 65535 groups, OpenGL 4.5's least count limit (a tile past the slice's last
    // lies outside the view and returns).
    const int row = std::min(inSlice, 65535);
    if (inSlice > 0) glDispatchCompute(GLuint(row), GLuint((inSlice + row - 1) / row), 1);
}

void runMarchListPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action) {
    if (stepsBeforeList(c, action) == 0) return;  // the list is empty
    setMarchUniforms(p.marchFromList, s, c, action);
    dispatchOverList(p, p.marchFromList.program.id(), s.marchList);
}

}  // namespace fraktal::viewport
