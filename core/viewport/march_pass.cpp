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
}

}  // namespace

void runMarchPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action) {
    const bool newView = action != FrameAction::Continue;
    const FormulaProgram& pass = newView ? p.marchFromStart : p.march;
    const GLuint program = pass.program.id();
    setMarchUniforms(pass, s, c, action);
    if (newView) {
        glUniform1i(pass.uniforms.resetAll, action == FrameAction::Reset ? 1 : 0);
        glUniform1i(pass.uniforms.coneTile, c.options.coneTile);
        glBindTextureUnit(1, s.reprojColor);
        glBindTextureUnit(2, s.reprojCarried);
        // MarchState::accum needs no reset: every pixel starts a new sample 0, whose colour
        // replaces the sum (viewport_accumulate.comp).
    }
    s.clearShadeList();
    s.clearMarchList();
    gl::dispatchOver(program, s.width(), s.height());
    imageBarrier();
}

void runMarchListPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action) {
    if (stepsBeforeList(c, action) == 0) return;  // the list is empty
    setMarchUniforms(p.marchFromList, s, c, action);
    dispatchOverList(p, p.marchFromList.program.id(), s.marchList);
}

}  // namespace fraktal::viewport
