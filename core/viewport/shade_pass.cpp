// Shading of finished samples only (shaders/viewport_shade.comp), over the shade list the march
// pass built: an indirect dispatch of as many 64-wide groups as the list needs.
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runShadePass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c) {
    const GLuint program = p.shade.program.id();
    p.shade.use(s, c.formula, c.shading);
    setViewUniforms(p.shade.uniforms, c.camera, s.width(), s.height(), c.lens);
    glUniform1i(p.shade.uniforms.atRest, c.atRest ? 1 : 0);
    glUniform1i(p.shade.uniforms.maxCarryFrames, c.options.maxCarryFrames);
    dispatchOverList(p, program, s.shadeList);
}

}  // namespace fraktal::viewport
