// The optional low-resolution cone pre-pass (shaders/viewport_cone.comp).
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runConePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c) {
    const GLuint program = p.cone.program.id();
    p.cone.use(s, c.formula, c.shading);
    setViewUniforms(p.cone.uniforms, c.camera, s.width(), s.height());
    glUniform1i(p.cone.uniforms.coneTile, c.options.coneTile);
    glUniform1i(p.cone.uniforms.coneSteps, c.options.coneSteps);
    const int tile = c.options.coneTile;
    gl::dispatchOver(program, (s.width() + tile - 1) / tile, (s.height() + tile - 1) / tile);
    imageBarrier();
}

}  // namespace fraktal::viewport
