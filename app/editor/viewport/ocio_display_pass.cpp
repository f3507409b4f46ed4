#include "app/editor/viewport/ocio_display_pass.hpp"

#include <cmath>
#include <stdexcept>

#include "core/gl/portable_limits.hpp"
#include "core/shader_library.hpp"

namespace fraktal::editor {

namespace {

constexpr std::string_view kMarker = "// OCIO_SHADER_TEXT";

ShaderSource templateSource(std::string_view name, std::string text) {
    ShaderSource s;
    s.text = std::move(text);
    s.programName = "shaders/" + std::string(name);
    return s;
}

GLint filterOf(OCIO::Interpolation i) { return i == OCIO::INTERP_NEAREST ? GL_NEAREST : GL_LINEAR; }

void setSampling(GLuint texture, OCIO::Interpolation interpolation) {
    glTextureParameteri(texture, GL_TEXTURE_MIN_FILTER, filterOf(interpolation));
    glTextureParameteri(texture, GL_TEXTURE_MAG_FILTER, filterOf(interpolation));
    for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
        glTextureParameteri(texture, wrap, GL_CLAMP_TO_EDGE);
}

}  // namespace

OcioDisplayPass::OcioDisplayPass() { glCreateVertexArrays(1, &emptyVertexArray_); }

OcioDisplayPass::~OcioDisplayPass() {
    releaseLuts();
    glDeleteVertexArrays(1, &emptyVertexArray_);
}

void OcioDisplayPass::releaseLuts() {
    for (LutTexture& t : luts_) glDeleteTextures(1, &t.id);
    luts_.clear();
}

void OcioDisplayPass::configure(const ColorPipeline& color, const DisplayKey& key) {
    if (program_ && key == key_) return;
    color.checkDisplayView(key.display, key.view);
    const std::string source = color.resolveSpace(key.workingSpace);
    OCIO::GpuShaderDescRcPtr desc = OCIO::GpuShaderDesc::CreateShaderDesc();
    try {
        OCIO::DisplayViewTransformRcPtr t = OCIO::DisplayViewTransform::Create();
        t->setSrc(source.c_str());
        t->setDisplay(key.display.c_str());
        t->setView(key.view.c_str());
        desc->setLanguage(OCIO::GPU_LANGUAGE_GLSL_4_0);
        desc->setFunctionName("OCIODisplay");
        desc->setResourcePrefix("ocio_");
        color.config()->getProcessor(t)->getDefaultGPUProcessor()->extractGpuShaderInfo(desc);
    } catch (const OCIO::Exception& e) {
        throw std::runtime_error("OCIO config " + color.configPath().string() + ": " + e.what());
    }
    // The image takes texture unit 0 and the LUTs 1.. (draw()): OpenGL 4.5 guarantees a fragment
    // shader 16 (core/gl/portable_limits.hpp).
    const unsigned lutCount = desc->getNum3DTextures() + desc->getNumTextures();
    if (lutCount + 1 > unsigned(gl::PortableLimits::textureUnitsPerStage))
        throw std::runtime_error("OCIO config " + color.configPath().string() + ": the display transform needs " +
                                 std::to_string(lutCount) + " LUT textures; OpenGL 4.5 guarantees room for " +
                                 std::to_string(gl::PortableLimits::textureUnitsPerStage - 1) + " beside the image");
    // Dynamic properties would need uniforms; this pass creates none (exposure is our own gain).
    if (desc->getNumUniforms() != 0)
        throw std::runtime_error("OCIO config " + color.configPath().string() +
                                 ": the display transform needs dynamic uniforms, which the viewport does not set");
    // The template's marker line becomes OCIO's declarations and OCIODisplay().
    std::string text(shaderTemplate("editor_ocio_display.frag"));
    const size_t at = text.find(kMarker);
    if (at == std::string::npos) throw std::runtime_error("shaders/editor_ocio_display.frag: no OCIO marker line");
    text.replace(at, kMarker.size(), desc->getShaderText());
    gl::Program program = gl::compileGraphics(
        templateSource("editor_fullscreen.vert", std::string(shaderTemplate("editor_fullscreen.vert"))),
        templateSource("editor_ocio_display.frag", std::move(text)));

    // OCIO's LUTs (none for the shipped config's built-in transforms; a studio config's file
    // LUTs), as in OCIO's own OpenGL helper (src/libutils/oglapphelpers/glsl.cpp).
    std::vector<LutTexture> luts;
    for (unsigned i = 0; i < desc->getNum3DTextures(); ++i) {
        const char *name = nullptr, *sampler = nullptr;
        unsigned edge = 0;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        desc->get3DTexture(i, name, sampler, edge, interpolation);
        const float* values = nullptr;
        desc->get3DTextureValues(i, values);
        LutTexture t{0, GL_TEXTURE_3D, sampler};
        glCreateTextures(GL_TEXTURE_3D, 1, &t.id);
        glTextureStorage3D(t.id, 1, GL_RGB32F, GLsizei(edge), GLsizei(edge), GLsizei(edge));
        glTextureSubImage3D(t.id, 0, 0, 0, 0, GLsizei(edge), GLsizei(edge), GLsizei(edge), GL_RGB, GL_FLOAT, values);
        setSampling(t.id, interpolation);
        luts.push_back(std::move(t));
    }
    for (unsigned i = 0; i < desc->getNumTextures(); ++i) {
        const char *name = nullptr, *sampler = nullptr;
        unsigned width = 0, height = 0;
        OCIO::GpuShaderDesc::TextureType channels = OCIO::GpuShaderDesc::TEXTURE_RGB_CHANNEL;
        OCIO::Interpolation interpolation = OCIO::INTERP_LINEAR;
        desc->getTexture(i, name, sampler, width, height, channels, interpolation);
        const float* values = nullptr;
        desc->getTextureValues(i, values);
        const bool red = channels == OCIO::GpuShaderDesc::TEXTURE_RED_CHANNEL;
        LutTexture t{0, height > 1 ? GLenum(GL_TEXTURE_2D) : GLenum(GL_TEXTURE_1D), sampler};
        glCreateTextures(t.target, 1, &t.id);
        if (t.target == GL_TEXTURE_2D) {
            glTextureStorage2D(t.id, 1, red ? GL_R32F : GL_RGB32F, GLsizei(width), GLsizei(height));
            glTextureSubImage2D(t.id, 0, 0, 0, GLsizei(width), GLsizei(height), red ? GL_RED : GL_RGB, GL_FLOAT,
                                values);
        } else {
            glTextureStorage1D(t.id, 1, red ? GL_R32F : GL_RGB32F, GLsizei(width));
            glTextureSubImage1D(t.id, 0, 0, GLsizei(width), red ? GL_RED : GL_RGB, GL_FLOAT, values);
        }
        setSampling(t.id, interpolation);
        luts.push_back(std::move(t));
    }

    releaseLuts();
    program_ = std::move(program);
    luts_ = std::move(luts);
    key_ = key;
    const GLuint id = program_.id();
    gainLocation_ = glGetUniformLocation(id, "u_gain");
    divideByCountLocation_ = glGetUniformLocation(id, "u_divideByCount");
    toWorkingLocation_ = glGetUniformLocation(id, "u_toWorking");
    // Each LUT's sampler keeps unit 1 + its index: set once, as the program's own state.
    for (size_t i = 0; i < luts_.size(); ++i)
        glProgramUniform1i(id, glGetUniformLocation(id, luts_[i].sampler.c_str()), GLint(i) + 1);
}

void OcioDisplayPass::draw(GLuint linearImage, double exposureStops, const SumInput& input) const {
    if (!program_) return;
    const GLuint program = program_.id();
    glUseProgram(program);
    glUniform1f(gainLocation_, float(std::exp2(exposureStops)));
    glUniform1i(divideByCountLocation_, input.divideByCount ? 1 : 0);
    const glm::mat3 toWorking(input.toWorking);
    glUniformMatrix3fv(toWorkingLocation_, 1, GL_FALSE, &toWorking[0][0]);
    glBindTextureUnit(0, linearImage);
    for (size_t i = 0; i < luts_.size(); ++i) glBindTextureUnit(GLuint(i) + 1, luts_[i].id);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glBindVertexArray(emptyVertexArray_);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glBindVertexArray(0);
    glUseProgram(0);
}

}  // namespace fraktal::editor
