#include "core/render/still_renderer.hpp"

#include <stdexcept>
#include <string>
#include <vector>

#include "core/gl/camera_uniforms.hpp"
#include "core/render/filter.hpp"
#include "core/shader_library.hpp"

namespace fraktal::gl {

namespace {
constexpr int kFilterTableSize = 65;  // FILTER_TABLE_SIZE in shaders/still.frag

std::string stillProgramSource() {
    return std::string(shaderTemplate("march.glsl")) + "\n" + std::string(shaderTemplate("shade.glsl")) + "\n" +
           std::string(shaderTemplate("camera.glsl")) + "\n" + std::string(shaderTemplate("lens.glsl")) + "\n" +
           std::string(shaderTemplate("still.frag"));
}
}  // namespace

StillRenderer::StillRenderer(const Formula& formula, int tileSize)
    : structure_(formula.structureKey()), tileSize_(tileSize) {
    const GeneratedFormula generated = generateFormulaGLSL(formula);
    program_ = compileGraphics(assembleShader(generated, "fullscreen.vert", shaderTemplate("fullscreen.vert")),
                               assembleShader(generated, "still.frag", stillProgramSource()));
    formulaUniforms_ = FormulaUniforms(program_.id(), formula);
    shadingUniforms_ = ShadingUniforms(program_.id());
    const auto at = [p = program_.id()](const char* name) { return glGetUniformLocation(p, name); };
    at_.camera = CameraLocations(program_.id());
    at_.lens = LensLocations(program_.id());
    at_.tileOrigin = at("u_tileOrigin");
    at_.imageSize = at("u_imageSize");
    at_.spp = at("u_spp");
    at_.maxSteps = at("u_maxSteps");
    at_.filterRadius = at("u_filterRadius");
    at_.transparentBackground = at("u_transparentBackground");
    at_.adaptiveTolerance = at("u_adaptiveTolerance");
    at_.filterInverseCdf = at("u_filterInverseCdf");

    glCreateFramebuffers(1, &framebuffer_);
    glCreateTextures(GL_TEXTURE_2D, 4, targets_);
    GLenum buffers[4];
    for (int i = 0; i < 4; ++i) {
        glTextureStorage2D(targets_[i], 1, GL_RGBA32F, tileSize, tileSize);
        glNamedFramebufferTexture(framebuffer_, GLenum(GL_COLOR_ATTACHMENT0 + i), targets_[i], 0);
        buffers[i] = GLenum(GL_COLOR_ATTACHMENT0 + i);
    }
    glNamedFramebufferDrawBuffers(framebuffer_, 4, buffers);
    if (glCheckNamedFramebufferStatus(framebuffer_, GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw std::runtime_error("still renderer: the float render targets are not supported by this GL driver");
    glCreateVertexArrays(1, &vertexArray_);
}

StillRenderer::~StillRenderer() {
    glDeleteVertexArrays(1, &vertexArray_);
    glDeleteTextures(4, targets_);
    glDeleteFramebuffers(1, &framebuffer_);
}

void StillRenderer::setScene(const Formula& formula, const Camera& camera, const RenderSettings& render,
                             const ShadingParams& shading, double adaptiveTolerance, const ThinLens& lens) {
    if (formula.structureKey() != structure_)
        throw std::logic_error("StillRenderer::setScene: the formula's structure changed; make a new renderer");
    imageWidth_ = render.width;
    imageHeight_ = render.height;
    const GLuint p = program_.id();
    glUseProgram(p);
    formulaUniforms_.upload(formula);
    shadingUniforms_.upload(shading);
    gl::setCameraUniforms(at_.camera, camera);
    gl::setLensUniforms(at_.lens, lens, camera);
    glUniform2i(at_.imageSize, render.width, render.height);
    glUniform1i(at_.spp, render.spp);
    glUniform1i(at_.maxSteps, render.maxSteps);
    glUniform1f(at_.filterRadius, float(render.filterRadius));
    glUniform1i(at_.transparentBackground, render.transparentBackground ? 1 : 0);
    glUniform1f(at_.adaptiveTolerance, float(adaptiveTolerance));
    const std::vector<float> table = blackmanHarrisInverseCdfTable(kFilterTableSize);
    glUniform1fv(at_.filterInverseCdf, kFilterTableSize, table.data());
}

void StillRenderer::renderTile(const TileRect& tile, ImageStrip& strip) {
    if (tile.width > tileSize_ || tile.height > tileSize_ || tile.y < strip.y0 ||
        tile.y + tile.height > strip.y0 + strip.rows || tile.x + tile.width > strip.width)
        throw std::logic_error("StillRenderer::renderTile: tile outside the strip or larger than the targets");
    glUseProgram(program_.id());
    glUniform2i(at_.tileOrigin, tile.x, tile.y);
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_);
    glViewport(0, 0, tile.width, tile.height);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);

    std::vector<float> pixels(size_t(tile.width) * size_t(tile.height) * 4);
    std::vector<float>* outputs[4] = {&strip.rgba, &strip.normalDepth, &strip.albedoAO, &strip.stats};
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    for (int i = 0; i < 4; ++i) {
        glReadBuffer(GLenum(GL_COLOR_ATTACHMENT0 + i));
        glReadPixels(0, 0, tile.width, tile.height, GL_RGBA, GL_FLOAT, pixels.data());
        // Framebuffer row j is image row tile.y + j (still.frag).
        for (int j = 0; j < tile.height; ++j) {
            const float* src = pixels.data() + size_t(j) * size_t(tile.width) * 4;
            float* dst =
                outputs[i]->data() + (size_t(tile.y - strip.y0 + j) * size_t(strip.width) + size_t(tile.x)) * 4;
            std::copy(src, src + size_t(tile.width) * 4, dst);
        }
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace fraktal::gl
