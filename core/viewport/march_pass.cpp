// Progressive marching, and on a new view the rays' starts (shaders/viewport_march.comp with
// shaders/viewport_start.glsl).
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runMarchPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, FrameAction action) {
    const bool newView = action != FrameAction::Continue;
    const FormulaProgram& pass = newView ? p.marchFromStart : p.march;
    const GLuint program = pass.program.id();
    pass.use(c.formula, c.shading);
    setViewUniforms(program, c.camera, s.width(), s.height());
    setInt(program, "u_stepsPerFrame", c.options.stepsPerFrame);
    setInt(program, "u_maxSteps", c.maxSteps);
    setInt(program, "u_atRest", c.atRest ? 1 : 0);
    setInt(program, "u_maxCarryFrames", c.options.maxCarryFrames);  // keepsCarriedColour
    setInt(program, "u_coarseHits", c.options.coarseHits ? 1 : 0);
    if (newView) {
        setInt(program, "u_resetAll", action == FrameAction::Reset ? 1 : 0);
        setInt(program, "u_coneTile", c.options.coneTile);
        glBindImageTexture(12, s.reprojDepth, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32UI);
        glBindTextureUnit(1, s.reprojColor);
        glBindTextureUnit(2, s.reprojCarried);
        // MarchState::accum needs no reset: every pixel starts a new sample 0, whose colour
        // replaces the sum (viewport_accumulate.comp).
    }
    s.clearShadeList();
    gl::dispatchOver(program, s.width(), s.height());
    imageBarrier();
}

}  // namespace fraktal::viewport
