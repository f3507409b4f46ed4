// Progressive marching (shaders/viewport_march.comp).
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runMarchPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c) {
    const GLuint program = p.march.program.id();
    p.march.use(c.formula, c.shading);
    setViewUniforms(program, c.camera, s.width(), s.height());
    setInt(program, "u_stepsPerFrame", c.options.stepsPerFrame);
    setInt(program, "u_maxSteps", c.maxSteps);
    setInt(program, "u_atRest", c.atRest ? 1 : 0);
    setInt(program, "u_maxCarryFrames", c.options.maxCarryFrames);  // keepsCarriedColour skips refining
    setInt(program, "u_coarseHits", c.options.coarseHits ? 1 : 0);
    s.clearShadeList();
    dispatchPixels(s.width(), s.height());
    imageBarrier();
}

}  // namespace fraktal::viewport
