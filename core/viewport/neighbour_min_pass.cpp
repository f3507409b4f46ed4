// Ray starts for a new view: the seed's second erosion fix after reprojection, or a full reset
// (shaders/viewport_neighbour_min.comp).
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runNeighbourMinPass(const ViewportPrograms& p, const MarchState& s, const FrameContext& c, bool resetAll) {
    const GLuint program = p.neighbourMin.program.id();
    p.neighbourMin.use(c.formula, c.shading);
    setViewUniforms(program, c.camera, s.width(), s.height());
    setInt(program, "u_resetAll", resetAll ? 1 : 0);
    setInt(program, "u_coneTile", c.options.coneTile);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, s.reprojDepth);
    // Every pixel starts a new sample 0. A clear, not a store in the shader: on llvmpipe each
    // image store costs a full-screen pass about 1.5 ms at 640x360.
    const float none[4] = {0, 0, 0, 0};
    glClearTexImage(s.accum, 0, GL_RGBA, GL_FLOAT, none);
    glBindTextureUnit(1, s.reprojColor);
    glBindTextureUnit(2, s.reprojCarried);
    dispatchPixels(s.width(), s.height());
    imageBarrier();
}

}  // namespace fraktal::viewport
