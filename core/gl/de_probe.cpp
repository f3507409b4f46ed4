#include "core/gl/de_probe.hpp"

#include <cmath>
#include <stdexcept>

#include "core/shader_library.hpp"

namespace fraktal::gl {

DEProbe::DEProbe(const Formula& formula) : structure_(formula.structureKey()) {
    program_ =
        compileCompute(assembleShader(generateFormulaGLSL(formula), "de_probe.comp", shaderTemplate("de_probe.comp")));
    uniforms_ = FormulaUniforms(program_.id(), formula);
    countLocation_ = glGetUniformLocation(program_.id(), "u_count");
    glCreateBuffers(2, buffers_);
}

DEProbe::~DEProbe() { glDeleteBuffers(2, buffers_); }

std::vector<GpuSample> DEProbe::evaluate(const Formula& formula, std::span<const vec3> points) {
    if (formula.structureKey() != structure_)
        throw std::logic_error("DEProbe::evaluate: the formula's structure changed; make a new probe");
    std::vector<glm::vec4> in(points.size());
    for (size_t i = 0; i < points.size(); ++i) in[i] = glm::vec4(glm::vec3(points[i]), 1.0f);
    const GLsizeiptr inBytes = GLsizeiptr(std::max<size_t>(1, in.size()) * sizeof(glm::vec4));
    glNamedBufferData(buffers_[0], inBytes, in.data(), GL_STREAM_DRAW);
    glNamedBufferData(buffers_[1], 2 * inBytes, nullptr, GL_STREAM_READ);
    glUseProgram(program_.id());
    uniforms_.upload(formula);
    glUniform1ui(countLocation_, GLuint(points.size()));
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffers_[0]);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, buffers_[1]);
    glDispatchCompute(GLuint((points.size() + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::vec4> out(2 * points.size());
    glGetNamedBufferSubData(buffers_[1], 0, GLsizeiptr(out.size() * sizeof(glm::vec4)), out.data());
    std::vector<GpuSample> samples(points.size());
    for (size_t i = 0; i < points.size(); ++i)
        samples[i] = {out[2 * i].x, int(out[2 * i].y), out[2 * i].z > 0.5f, out[2 * i + 1],
                      int(std::lround(out[2 * i].w))};
    return samples;
}

void GpuSampler::evaluate(std::span<const vec3> points, std::span<Evaluation> out) {
    const std::vector<GpuSample> samples = probe_.evaluate(formula_, points);
    for (size_t i = 0; i < samples.size(); ++i) {
        Evaluation& e = out[i];
        e.distance = samples[i].distance;
        e.iterations = samples[i].iterations;
        e.escaped = samples[i].escaped;
        e.trap.value = vec4(samples[i].trap);
        e.surface = samples[i].surface;
        e.inside = isInside(*formula_.estimator.block, e.distance, e.escaped);
    }
}

}  // namespace fraktal::gl
