// Display transform (shaders/viewport_display.frag): the image stays scene-linear until here.
#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

void runDisplayPass(const ViewportPrograms& p, const MarchState& s, float exposure, bool flipY, GLuint vertexArray) {
    const GLuint program = p.display.id();
    glUseProgram(program);
    glUniform1f(p.display.uniforms.exposure, exposure);
    glUniform1i(p.display.uniforms.flipY, flipY ? 1 : 0);
    glBindTextureUnit(0, s.shown);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vertexArray);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
}

}  // namespace fraktal::viewport
