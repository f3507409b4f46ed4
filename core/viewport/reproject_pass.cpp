// Reprojection (seed 4.2): one vertex per pixel at the point its centre ray reached, a quad
// between each 2x2 block of pixels, rasterised with the new view-projection; the depth test keeps
// the nearest surface where quads overlap. Pixels no quad covers stay at -1 and restart.
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <vector>

#include "core/viewport/passes.hpp"

namespace fraktal::viewport {

ReprojectPass::ReprojectPass() {
    glCreateVertexArrays(1, &vertexArray_);
    glCreateBuffers(1, &indices_);
}

ReprojectPass::~ReprojectPass() {
    glDeleteBuffers(1, &indices_);
    glDeleteVertexArrays(1, &vertexArray_);
}

void ReprojectPass::run(const ViewportPrograms& p, const MarchState& s, const Camera& previous, const Camera& current,
                        double boundRadius) {
    const int w = s.width(), h = s.height();
    if (w != width_ || h != height_) {
        std::vector<GLuint> index;
        index.reserve(size_t(w - 1) * size_t(h - 1) * 6);
        for (int y = 0; y + 1 < h; ++y)
            for (int x = 0; x + 1 < w; ++x) {
                const GLuint a = GLuint(y * w + x), b = a + 1, c = a + GLuint(w), d = c + 1;
                index.insert(index.end(), {a, b, c, b, d, c});
            }
        glNamedBufferData(indices_, GLsizeiptr(index.size() * sizeof(GLuint)), index.data(), GL_STATIC_DRAW);
        glVertexArrayElementBuffer(vertexArray_, indices_);
        indexCount_ = GLsizei(index.size());
        width_ = w;
        height_ = h;
    }
    // Clip space of the new camera; y flipped because image rows count from the top.
    const double distance = glm::length(current.position);
    const double nearPlane = 1e-4 * boundRadius, farPlane = 4.0 * (distance + boundRadius);
    const glm::dmat4 projection = glm::perspective(glm::radians(current.fovY), double(w) / h, nearPlane, farPlane);
    const glm::dmat4 flip = glm::scale(glm::dmat4(1.0), glm::dvec3(1.0, -1.0, 1.0));
    const glm::mat4 clipFromWorld(flip * projection * glm::lookAt(current.position, current.target, current.up));

    glBindFramebuffer(GL_FRAMEBUFFER, s.reprojFramebuffer);
    glViewport(0, 0, w, h);
    const float nothing[4] = {-1.0f, 0.0f, -1.0f, 0.0f}, black[4] = {0, 0, 0, 0};
    const float farDepth = 1.0f;
    glClearNamedFramebufferfv(s.reprojFramebuffer, GL_COLOR, 0, nothing);
    glClearNamedFramebufferfv(s.reprojFramebuffer, GL_COLOR, 1, black);
    glClearNamedFramebufferfv(s.reprojFramebuffer, GL_DEPTH, 0, &farDepth);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);

    const GLuint program = p.reproject.id();
    glUseProgram(program);
    setViewUniforms(program, previous, w, h);
    glUniformMatrix4fv(glGetUniformLocation(program, "u_newClipFromWorld"), 1, GL_FALSE, glm::value_ptr(clipFromWorld));
    glUniform3f(glGetUniformLocation(program, "u_newCameraPosition"), float(current.position.x),
                float(current.position.y), float(current.position.z));
    glBindTextureUnit(0, s.centre);
    glBindTextureUnit(1, s.image);
    glBindVertexArray(vertexArray_);
    glDrawElements(GL_TRIANGLES, indexCount_, GL_UNSIGNED_INT, nullptr);
    glBindVertexArray(0);
    glDisable(GL_DEPTH_TEST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    imageBarrier();
}

}  // namespace fraktal::viewport
