// Shading of finished samples only (shaders/viewport_shade.comp).
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runShadePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c) {
    const GLuint program = p.shade.program.id();
    p.shade.use(c.formula, c.shading);
    setViewUniforms(program, c.camera, s.width(), s.height());
    setInt(program, "u_atRest", c.atRest ? 1 : 0);
    dispatchPixels(s.width(), s.height());
    imageBarrier();
}

}  // namespace fraktal::viewport
