// Reprojection (seed 4.2) as a compute scatter (shaders/viewport_reproject.comp): every previous
// pixel corner's vertex (at the nearest distance of the four pixels around it) goes to the new
// pixel it projects into, nearest first. Pixels nothing lands on
// stay at -1; the start pass fills one-pixel gaps from their neighbours and restarts the rest.
// Hit colours take a second scatter keyed by their own hit point (why: the shader's header), into
// the pixel each point lies in and, for pixels no point lies in, the nearest point around.
#include <limits>

#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

ReprojectPass::ReprojectPass() { glCreateBuffers(1, &depth_); }

ReprojectPass::~ReprojectPass() { glDeleteBuffers(1, &depth_); }

void ReprojectPass::run(const ViewportPrograms& p, const MarchState& s, const Camera& previous, const Camera& current,
                        double /*boundRadius*/) {
    const int w = s.width(), h = s.height();
    if (w != width_ || h != height_) {
        glNamedBufferData(depth_, GLsizeiptr(3 * size_t(w) * size_t(h) * sizeof(GLuint)), nullptr, GL_DYNAMIC_COPY);
        width_ = w;
        height_ = h;
    }
    const GLuint farthest = std::numeric_limits<GLuint>::max();
    glClearNamedBufferData(depth_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &farthest);
    const float nothing[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
    glClearTexImage(s.reprojDistance, 0, GL_RGBA, GL_FLOAT, nothing);
    const float noColor[4] = {0.0f, 0.0f, 0.0f, 0.0f};  // a = 0: nothing carried
    glClearTexImage(s.reprojColor, 0, GL_RGBA, GL_FLOAT, noColor);

    const GLuint program = p.reproject.id();
    glUseProgram(program);
    setViewUniforms(program, previous, w, h);
    // The new camera's basis, exactly as setViewUniforms builds it.
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
    glBindTextureUnit(0, s.centre);
    glBindTextureUnit(1, s.image);
    glBindImageTexture(7, s.reprojDistance, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(8, s.reprojColor, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindImageTexture(9, s.reprojCarried, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
    glBindTextureUnit(2, s.colourPoint);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, depth_);
    for (int resolve = 0; resolve <= 1; ++resolve) {
        setInt(program, "u_resolve", resolve);
        dispatchPixels(w, h);
        imageBarrier();
    }
}

}  // namespace fraktal::viewport
