// Reprojection (seed 4.2) as a compute scatter (shaders/viewport_reproject.comp): every previous
// pixel corner's vertex (at the nearest distance of the four pixels around it) goes to the new
// pixel it projects into, nearest first. Pixels nothing lands on keep the key "none"; the start
// pass fills one-pixel gaps from their neighbours and restarts the rest. Hit colours take a
// second scatter keyed by their own hit point (why: the shader's header), into the pixel each
// point lies in and, for pixels no point lies in, the nearest point around.
#include <limits>

#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

namespace {

// The view uniforms of the previous camera (the points' rays) and the new camera's basis,
// exactly as setViewUniforms builds it.
void setCameraUniforms(GLuint program, const Camera& previous, const Camera& current, int width, int height) {
    glUseProgram(program);
    setViewUniforms(program, previous, width, height);
    const vec3 forward = normalize(current.target - current.position);
    const vec3 right = normalize(glm::cross(forward, current.up));
    const vec3 up = glm::cross(right, forward);
    auto set3 = [&](const char* name, const vec3& v) {
        glUniform3f(glGetUniformLocation(program, name), float(v.x), float(v.y), float(v.z));
    };
    set3("u_newCameraPosition", current.position);
    set3("u_newRight", right);
    set3("u_newUp", up);
    set3("u_newForward", forward);
    setFloat(program, "u_newTanHalfFovY", float(std::tan(glm::radians(current.fovY) * 0.5)));
}

}  // namespace

void runReprojectPass(const ViewportPrograms& p, const MarchState& s, const Camera& previous, const Camera& current) {
    const int w = s.width(), h = s.height();
    const GLuint none = std::numeric_limits<GLuint>::max();
    glClearNamedBufferData(s.reprojDepth, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &none);
    const float noColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // a = 0: nothing carried
    glClearTexImage(s.reprojColor, 0, GL_RGBA, GL_FLOAT, noColor);
    glBindTextureUnit(0, s.centre);
    glBindTextureUnit(1, s.image);
    glBindTextureUnit(2, s.colourPoint);
    glBindImageTexture(8, s.reprojColor, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(9, s.reprojCarried, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, s.reprojDepth);
    for (const gl::Program* pass : {&p.reprojectClaim, &p.reprojectWrite}) {
        setCameraUniforms(pass->id(), previous, current, w, h);
        dispatchPixels(w, h);
        imageBarrier();
    }
}

}  // namespace fraktal::viewport
