#include "app/editor/preview_viewport.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>

#include "app/editor/document.hpp"
#include "core/shader_library.hpp"

namespace fraktal::editor {

std::unique_ptr<ViewportView> makeViewportView() { return std::make_unique<PreviewViewport>(); }

namespace {

ShaderSource plainSource(std::string_view name) {
    ShaderSource s;
    s.text = std::string(shaderTemplate(name));
    s.programName = "shaders/" + std::string(name);
    return s;
}

GLuint makeTexture(GLenum format, int w, int h, int levels = 1) {
    GLuint t = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &t);
    glTextureStorage2D(t, levels, format, w, h);
    glTextureParameteri(t, GL_TEXTURE_MIN_FILTER, levels > 1 ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(t, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTextureParameteri(t, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return t;
}

// Halton (2, 3): well-spread subpixel offsets for progressive anti-aliasing.
double halton(int index, int base) {
    double f = 1.0, r = 0.0;
    for (int i = index + 1; i > 0; i /= base) {
        f /= base;
        r += f * (i % base);
    }
    return r;
}

}  // namespace

void PreviewTargets::resize(int w, int h) {
    if (w == width && h == height) return;
    release();
    width = w;
    height = h;
    const int levels = 1 + int(std::floor(std::log2(double(std::max(w, h)))));
    accumulated = makeTexture(GL_RGBA32F, w, h);
    evaluations = makeTexture(GL_RG32F, w, h, levels);
    display = makeTexture(GL_RGBA8, w, h);
    glCreateFramebuffers(1, &marchFbo);
    glNamedFramebufferTexture(marchFbo, GL_COLOR_ATTACHMENT0, accumulated, 0);
    glNamedFramebufferTexture(marchFbo, GL_COLOR_ATTACHMENT1, evaluations, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glNamedFramebufferDrawBuffers(marchFbo, 2, buffers);
    glCreateFramebuffers(1, &displayFbo);
    glNamedFramebufferTexture(displayFbo, GL_COLOR_ATTACHMENT0, display, 0);
    // Start black, so a first failed compile shows an empty viewport rather than garbage.
    const float zero[4] = {0, 0, 0, 0};
    glClearNamedFramebufferfv(marchFbo, GL_COLOR, 0, zero);
    glClearNamedFramebufferfv(displayFbo, GL_COLOR, 0, zero);
}

void PreviewTargets::release() {
    const GLuint textures[] = {accumulated, evaluations, display};
    glDeleteTextures(3, textures);
    const GLuint fbos[] = {marchFbo, displayFbo};
    glDeleteFramebuffers(2, fbos);
    *this = PreviewTargets{};
}

PreviewViewport::PreviewViewport() {
    display_ = gl::compileGraphics(plainSource("editor_fullscreen.vert"), plainSource("editor_display.frag"));
    glCreateVertexArrays(1, &emptyVao_);
}

PreviewViewport::~PreviewViewport() {
    targets_.release();
    glDeleteVertexArrays(1, &emptyVao_);
}

bool PreviewViewport::ensureProgram(const Formula& formula) {
    if (!tracker_.needsRecompile(formula)) return true;
    const std::string key = formula.structureKey();
    if (key == failedStructure_) return false;
    try {
        const ShaderSource fragment = assembleShader(generateFormulaGLSL(formula), "shaders/editor_preview.frag",
                                                     shaderTemplate("editor_preview.frag"));
        gl::Program program = gl::compileGraphics(plainSource("editor_fullscreen.vert"), fragment);
        march_ = std::move(program);
        uniforms_ = gl::FormulaUniforms(march_.id(), formula);
        tracker_.compiled(formula);
        ++stats_.compiles;
        failedStructure_.clear();
        compileError_.clear();
        imageKey_.clear();
        return true;
    } catch (const std::exception& e) {
        failedStructure_ = key;
        compileError_ = e.what();
        return false;
    }
}

void PreviewViewport::marchOneSample(const Formula& formula, const Camera& camera, const ViewSettings& s) {
    const int sample = stats_.samples;
    const GLuint p = march_.id();
    glUseProgram(p);
    uniforms_.upload(formula);
    auto loc = [p](const char* name) { return glGetUniformLocation(p, name); };
    glUniform2f(loc("u_resolution"), float(targets_.width), float(targets_.height));
    // The first sample goes through pixel centres so that an unconverged image is not shifted.
    const float jx = sample == 0 ? 0.0f : float(halton(sample, 2) - 0.5);
    const float jy = sample == 0 ? 0.0f : float(halton(sample, 3) - 0.5);
    glUniform2f(loc("u_jitter"), jx, jy);
    const glm::mat4 worldFromCamera(camera.worldFromCamera());
    glUniformMatrix4fv(loc("u_worldFromCamera"), 1, GL_FALSE, &worldFromCamera[0][0]);
    glUniform1f(loc("u_tanHalfFov"), float(std::tan(glm::radians(camera.fovY) * 0.5)));
    glUniform1i(loc("u_maxSteps"), s.maxSteps);
    const glm::vec3 light(normalize(s.lightDirection == vec3(0.0) ? vec3(0, 1, 0) : s.lightDirection));
    glUniform3f(loc("u_lightDir"), light.x, light.y, light.z);
    glUniform1i(loc("u_shadows"), s.shadows);
    glUniform1i(loc("u_ambientOcclusion"), s.ambientOcclusion);
    glUniform1f(loc("u_fog"), float(s.fog / std::max(formula.boundRadius, 1e-3)));
    glUniform1i(loc("u_palette"), s.palette);

    glBindFramebuffer(GL_FRAMEBUFFER, targets_.marchFbo);
    glViewport(0, 0, targets_.width, targets_.height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_CULL_FACE);
    // Radiance sums over samples; the statistics target keeps only this frame's values.
    glEnablei(GL_BLEND, 0);
    glBlendFunci(0, GL_ONE, GL_ONE);
    glBlendEquationi(0, GL_FUNC_ADD);
    glDisablei(GL_BLEND, 1);
    if (sample == 0) {
        const float zero[4] = {0, 0, 0, 0};
        glClearNamedFramebufferfv(targets_.marchFbo, GL_COLOR, 0, zero);
    }
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glDisablei(GL_BLEND, 0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    ++stats_.samples;
}

void PreviewViewport::updateStats() {
    // Mean evaluations and hit share: the 1x1 top mip of the statistics image.
    glGenerateTextureMipmap(targets_.evaluations);
    const int top = int(std::floor(std::log2(double(std::max(targets_.width, targets_.height)))));
    float mean[2] = {0, 0};
    glGetTextureSubImage(targets_.evaluations, top, 0, 0, 0, 1, 1, 1, GL_RG, GL_FLOAT, sizeof(mean), mean);
    // A mip level of a non-square, non-power-of-two image averages unevenly at the edges: a
    // close estimate, good enough for an overlay.
    stats_.deEvaluationsPerPixel = mean[0];
    stats_.hitShare = mean[1];
}

void PreviewViewport::display(const ViewSettings& s) {
    glUseProgram(display_.id());
    glUniform1f(glGetUniformLocation(display_.id(), "u_exposureScale"), float(std::exp2(s.exposure)));
    glBindTextureUnit(0, targets_.accumulated);
    glBindFramebuffer(GL_FRAMEBUFFER, targets_.displayFbo);
    glViewport(0, 0, targets_.width, targets_.height);
    glDisable(GL_BLEND);
    glBindVertexArray(emptyVao_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

void PreviewViewport::render(const Formula& formula, const Camera& camera, const ViewSettings& settings, int width,
                             int height) {
    width = std::max(width, 1);
    height = std::max(height, 1);
    const auto start = std::chrono::steady_clock::now();
    stats_.renderMs = 0.0;
    stats_.aaCap = settings.reprojection ? std::max(settings.aaCap, 1) : 1;
    if (!ensureProgram(formula)) return;  // the last good image stays

    // What the accumulated samples depend on (exposure only affects the display pass).
    ViewSettings shading = settings;
    shading.exposure = 0.0;
    Preset scene;
    scene.formula = formula;
    scene.camera = camera;
    const std::string key = presetToJson(scene).dump() + viewSettingsToJson(shading).dump() + std::to_string(width) +
                            "x" + std::to_string(height);
    const bool sameImage = key == imageKey_ && settings.reprojection;
    if (!sameImage) {
        targets_.resize(width, height);
        stats_.samples = 0;
        imageKey_ = key;
    }
    stats_.width = width;
    stats_.height = height;
    if (stats_.samples < stats_.aaCap) {
        marchOneSample(formula, camera, settings);
        updateStats();
    }
    display(settings);
    glFinish();
    stats_.renderMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    stats_.convergedShare = stats_.samples >= stats_.aaCap ? 1.0 : 0.0;
    stats_.reprojectedShare = stats_.samples > 1 ? 1.0 : 0.0;
}

}  // namespace fraktal::editor
