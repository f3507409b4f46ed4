// Reprojection (seed 4.2) as a compute scatter (shaders/viewport_reproject.comp): every previous
// pixel corner's vertex (at the nearest distance of the four pixels around it) goes to the new
// pixel it projects into, nearest first. Pixels nothing lands on keep the key "none"; the rays'
// starts (viewport_start.glsl) fill one-pixel gaps from their neighbours and restart the rest.
// Hit colours take a second scatter keyed by their own hit point (why: the shader's header), into
// the pixel each point lies in and, for pixels no point lies in, the nearest point around. Onto a
// smaller grid an invocation scatters a block of points (reprojectBlock; the shader says why).
#include <algorithm>
#include <limits>

#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

int reprojectBlock(int oldWidth, int oldHeight, int newWidth, int newHeight) {
    return std::clamp(std::min(oldWidth / newWidth, oldHeight / newHeight) / 2, 1, kMaxReprojectBlock);
}

void runReprojectPass(const ViewportPrograms& p, const MarchState& from, const MarchState& s, const Camera& previous,
                      const Camera& current) {
    const int w = from.width(), h = from.height();
    const int block = reprojectBlock(w, h, s.width(), s.height());
    const GLuint none = std::numeric_limits<GLuint>::max();
    glClearTexImage(s.reprojDepth, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    const float noColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // a = 0: nothing carried
    glClearTexImage(s.reprojColor, 0, GL_RGBA, GL_FLOAT, noColor);
    glBindTextureUnit(0, from.centre);
    glBindTextureUnit(1, from.image);
    glBindTextureUnit(2, from.colourPoint);
    const Pass* claim = block > 1 ? &p.reprojectBlockClaim : &p.reprojectClaim;
    const Pass* write = block > 1 ? &p.reprojectBlockWrite : &p.reprojectWrite;
    for (const Pass* pass : {claim, write}) {
        pass->use(s);
        setViewUniforms(pass->uniforms, previous, w, h);  // the points' rays
        glUniform2i(pass->uniforms.newSize, s.width(), s.height());
        glUniform1i(pass->uniforms.generation, from.generation);  // the points' view
        glUniform1i(pass->uniforms.block, block);
        gl::setCameraUniforms(pass->uniforms.newCamera, current);
        gl::dispatchOver(pass->id(), (w + block - 1) / block, (h + block - 1) / block);
        imageBarrier();
    }
}

}  // namespace fraktal::viewport
