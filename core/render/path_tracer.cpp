#include "core/render/path_tracer.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "core/gl/camera_uniforms.hpp"
#include "core/shader_library.hpp"

namespace fraktal::gl {

namespace {
constexpr int kMaxLightsInShader = 16;  // MAX_LIGHTS in shaders/pathtrace.frag
static_assert(kMaxLightsInShader == kMaxLights);

std::string pathTraceProgramSource() {
    return std::string(shaderTemplate("march.glsl")) + "\n" + std::string(shaderTemplate("shade.glsl")) + "\n" +
           std::string(shaderTemplate("camera.glsl")) + "\n" + std::string(shaderTemplate("lens.glsl")) + "\n" +
           std::string(shaderTemplate("pathtrace.frag"));
}

template <class T>
void uploadBuffer(GLuint buffer, const std::vector<T>& values) {
    std::vector<float> f(values.begin(), values.end());
    if (f.empty()) f.push_back(0.0f);
    glNamedBufferData(buffer, GLsizeiptr(f.size() * sizeof(float)), f.data(), GL_STATIC_DRAW);
}
}  // namespace

PathTracer::PathTracer(const Formula& formula, int width, int height)
    : structure_(formula.structureKey()), width_(width), height_(height) {
    const GeneratedFormula generated = generateFormulaGLSL(formula);
    program_ = compileGraphics(assembleShader(generated, "fullscreen.vert", shaderTemplate("fullscreen.vert")),
                               assembleShader(generated, "pathtrace.frag", pathTraceProgramSource()));
    formulaUniforms_ = FormulaUniforms(program_.id(), formula);
    shadingUniforms_ = ShadingUniforms(program_.id());
    cameraLocations_ = CameraLocations(program_.id());
    firstSampleLocation_ = glGetUniformLocation(program_.id(), "u_firstSample");
    writeDepthLocation_ = glGetUniformLocation(program_.id(), "u_writeDepth");
    samplesLocation_ = glGetUniformLocation(program_.id(), "u_samples");
    glCreateFramebuffers(1, &framebuffer_);
    glCreateTextures(GL_TEXTURE_2D, kPassCount, targets_);
    GLenum buffers[kPassCount];
    for (int i = 0; i < kPassCount; ++i) {
        glTextureStorage2D(targets_[i], 1, GL_RGBA32F, width, height);
        glNamedFramebufferTexture(framebuffer_, GLenum(GL_COLOR_ATTACHMENT0 + i), targets_[i], 0);
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    }
    glNamedFramebufferDrawBuffers(framebuffer_, kPassCount, buffers);
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("path tracer: the float render targets are not supported by this GL driver");
    glCreateVertexArrays(1, &vertexArray_);
    glCreateBuffers(3, envBuffers_);
}

PathTracer::~PathTracer() {
    glDeleteBuffers(3, envBuffers_);
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteTextures(kPassCount, targets_);
    glDeleteFramebuffers(1, &framebuffer_);
}

void PathTracer::setScene(const PathScene& scene, int firstSampleIndex) {
    if (scene.formula.structureKey() != structure_)
        throw std::logic_error("PathTracer::setScene: the formula's structure changed; make a new tracer");
    if (scene.render.width != width_ || scene.render.height != height_)
        throw std::logic_error("PathTracer::setScene: the image size changed; make a new tracer");
    const GLuint p = program_.id();
    glUseProgram(p);
    formulaUniforms_.upload(scene.formula);
    shadingUniforms_.upload(scene.shading);
    setCameraUniforms(cameraLocations_, scene.camera);
    auto loc = [&](const char* name) { return glGetUniformLocation(p, name); };
    glUniform2i(loc("u_imageSize"), width_, height_);
    glUniform1i(loc("u_maxSteps"), scene.render.maxSteps);
    glUniform1i(loc("u_transparentBackground"), scene.render.transparentBackground ? 1 : 0);
    const Lighting& l = scene.lighting;
    setLensUniforms(LensLocations(p), l.lens, scene.camera);
    glUniform1i(loc("u_bounces"), l.pathTrace.bounces);
    glUniform1f(loc("u_alpha"), float(l.pathTrace.roughness * l.pathTrace.roughness));
    glUniform1f(loc("u_f0"), float(l.pathTrace.specular));
    glUniform1f(loc("u_emission"), float(l.pathTrace.emission));
    int count = 0;
    for (const Light& light : l.lights) {
        if (!light.enabled) continue;
        const std::string i = "[" + std::to_string(count) + "]";
        const vec3 power = light.color * light.intensity;
        const vec3 vector = light.type == LightType::Directional ? light.direction : light.position;
        glUniform1i(loc(("u_lightType" + i).c_str()), int(light.type));
        glUniform3f(loc(("u_lightPower" + i).c_str()), float(power.x), float(power.y), float(power.z));
        glUniform3f(loc(("u_lightVector" + i).c_str()), float(vector.x), float(vector.y), float(vector.z));
        glUniform3f(loc(("u_lightNormal" + i).c_str()), float(light.normal.x), float(light.normal.y),
                    float(light.normal.z));
        glUniform3f(loc(("u_lightUp" + i).c_str()), float(light.up.x), float(light.up.y), float(light.up.z));
        glUniform3f(loc(("u_lightSize" + i).c_str()), float(light.size), float(light.height), 0.0f);
        ++count;
    }
    glUniform1i(loc("u_lightCount"), count);
    const EnvironmentMap& env = scene.environment;
    glUniform2i(loc("u_envSize"), env.width, env.height);
    glUniform1f(loc("u_envRotation"), float(env.rotation));
    glUniform1f(loc("u_envTotal"), float(env.total));
    glUniform1i(loc("u_envVisible"), l.environment.visible ? 1 : 0);
    uploadBuffer(envBuffers_[0], env.rgb);
    uploadBuffer(envBuffers_[1], env.marginal);
    uploadBuffer(envBuffers_[2], env.conditional);
    const float zero[4] = {0, 0, 0, 0};
    for (GLuint t : targets_) glClearTexImage(t, 0, GL_RGBA, GL_FLOAT, zero);
    samples_ = 0;
    rowsDone_ = 0;
    firstSampleIndex_ = firstSampleIndex;
}

void PathTracer::beginDraws() {
    glUseProgram(program_.id());
    for (int i = 0; i < 3; ++i) glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(i), envBuffers_[i]);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, width_, height_);
    glEnable(GL_BLEND);
    glBlendFunc(GL_ONE, GL_ONE);
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vertexArray_);
}

void PathTracer::endDraws() {
    glDisable(GL_BLEND);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PathTracer::draw(int samples) {
    glUniform1i(firstSampleLocation_, firstSampleIndex_ + samples_);
    glUniform1i(writeDepthLocation_, samples_ == 0 ? 1 : 0);
    glUniform1i(samplesLocation_, samples);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glFinish();  // one draw at a time: llvmpipe runs a queued batch of long draws at once
}

void PathTracer::addSamples(int samples, int batch) {
    if (rowsDone_ != 0) throw std::logic_error("PathTracer::addSamples: a pass of addSampleRows is under way");
    beginDraws();
    while (samples > 0) {
        const int n = std::min(samples, std::max(batch, 1));
        draw(n);
        samples_ += n;
        samples -= n;
    }
    endDraws();
}

bool PathTracer::addSampleRows(int rows) {
    rows = std::clamp(rows, 1, height_ - rowsDone_);
    beginDraws();
    // Only these rows' fragments run (texture rows, from the bottom; any order covers the image).
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, rowsDone_, width_, rows);
    draw(1);
    glDisable(GL_SCISSOR_TEST);
    endDraws();
    rowsDone_ += rows;
    if (rowsDone_ < height_) return false;
    rowsDone_ = 0;
    ++samples_;
    return true;
}

PathImage PathTracer::image() const {
    PathImage out;
    out.resize(width_, height_);
    out.spp = samples_;
    std::vector<float> pixels(size_t(width_) * size_t(height_) * 4);
    const float inv = 1.0f / float(std::max(samples_, 1));
    const size_t row = size_t(width_) * 4;
    for (int i = 0; i < kPassCount; ++i) {
        glGetTextureImage(targets_[i], 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
        for (int y = 0; y < height_; ++y) {  // texture row 0 is the image's bottom row
            const float* src = pixels.data() + size_t(height_ - 1 - y) * row;
            float* dst = out.passes[i].data() + size_t(y) * row;
            for (size_t k = 0; k < row; ++k) dst[k] = src[k] * inv;
        }
    }
    for (int y = 0; y < height_; ++y)  // the depth is written once, not summed; the DE count is a sum
        for (int x = 0; x < width_; ++x) {
            out.at(kNormal, x, y)[3] *= float(std::max(samples_, 1));
            out.at(kDiffuseDirect, x, y)[3] = 0.0f;
        }
    return out;
}

double PathTracer::deEvaluationsPerSample() const {
    std::vector<float> pixels(size_t(width_) * size_t(height_) * 4);
    glGetTextureImage(targets_[kDiffuseDirect], 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                      pixels.data());
    double sum = 0.0;
    for (size_t i = 3; i < pixels.size(); i += 4) sum += pixels[i];
    return sum / (double(width_) * height_ * std::max(samples_, 1));
}

}  // namespace fraktal::gl
