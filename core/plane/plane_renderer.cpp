#include "core/plane/plane_renderer.hpp"

#include <cstring>
#include <stdexcept>

#include "core/plane/plane_glsl.hpp"
#include "core/shader_library.hpp"

namespace fraktal {

bool planeFp64Available() {
    GLint major = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    if (major >= 4) return true;  // double is core GLSL from 4.00
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i)
        if (std::strcmp(reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i))),
                        "GL_ARB_gpu_shader_fp64") == 0)
            return true;
    return false;
}

PlaneTarget::~PlaneTarget() {
    if (colour_) glDeleteTextures(1, &colour_);
    if (aov_) glDeleteTextures(1, &aov_);
}

void PlaneTarget::resize(int width, int height) {
    if (width == width_ && height == height_ && colour_) return;
    if (colour_) glDeleteTextures(1, &colour_);
    if (aov_) glDeleteTextures(1, &aov_);
    for (GLuint* t : {&colour_, &aov_}) {
        glCreateTextures(GL_TEXTURE_2D, 1, t);
        glTextureStorage2D(*t, 1, GL_RGBA32F, width, height);
        glTextureParameteri(*t, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTextureParameteri(*t, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    width_ = width;
    height_ = height;
}

void PlaneRenderer::prepare(const PlaneFormula& formula, PlanePrecision precision) {
    warnings_.clear();
    bool wantDouble = precision != PlanePrecision::Float;
    if (wantDouble && !planeFp64Available()) {
        warnings_.push_back(
            "this GL driver has no double-precision shaders (GL_ARB_gpu_shader_fp64): rendering in "
            "float, so zooms below a view width of about 1e-5 turn blocky");
        wantDouble = false;
    }
    if (wantDouble && formula.needsFloatPower())
        warnings_.push_back(
            "a non-whole power runs in float on the GPU (GLSL has no double pow/atan): deep zooms "
            "of this formula turn blocky");
    const std::string key = formula.structureKey() + (wantDouble ? "#fp64" : "#fp32");
    if (key != key_ || !program_) {
        const GeneratedFormula generated = generatePlaneGLSL(formula);
        const ShaderSource source = assembleShader(generated, "plane_render.comp", shaderTemplate("plane_render.comp"),
                                                   wantDouble ? kPlaneFp64Define : std::string_view{});
        program_ = gl::compileCompute(source);
        key_ = key;
        double_ = wantDouble;
        paramLocations_.clear();
        int k = 0;
        auto locate = [&](const PlaneNode& n) {
            std::vector<GLint> locations;
            for (const ParamDecl& p : n.block->params)
                locations.push_back(glGetUniformLocation(program_.id(), planeUniformName(k, p.name).c_str()));
            paramLocations_.push_back(std::move(locations));
            ++k;
        };
        for (const PlaneNode& n : formula.start) locate(n);
        for (const PlaneNode& n : formula.nodes) locate(n);
        locate(formula.estimator);
        const auto at = [p = program_.id()](const char* name) { return glGetUniformLocation(p, name); };
        at_.iterations = at("u_iterations");
        at_.bailout = at("u_bailout");
        at_.center = at("u_center");
        at_.pixelSize = at("u_pixelSize");
        at_.imageSize = at("u_imageSize");
        at_.tileOrigin = at("u_tileOrigin");
        at_.tileSize = at("u_tileSize");
        at_.storeOrigin = at("u_storeOrigin");
        at_.sampleBegin = at("u_sampleBegin");
        at_.sampleCount = at("u_sampleCount");
        at_.accumulate = at("u_accumulate");
        at_.paletteA = at("u_paletteA");
        at_.paletteB = at("u_paletteB");
        at_.paletteC = at("u_paletteC");
        at_.paletteD = at("u_paletteD");
        at_.interior = at("u_interior");
        at_.paletteFrequency = at("u_paletteFrequency");
        at_.paletteOffset = at("u_paletteOffset");
        at_.edgeWidth = at("u_edgeWidth");
    }
}

void PlaneRenderer::render(const PlaneFormula& formula, const PlaneColouring& colouring, const PlaneViewRect& view,
                           const PlaneTile& tile, PlaneTarget& target, int sampleBegin, int sampleCount,
                           bool accumulate, bool inImage) {
    if (!program_) throw std::logic_error("PlaneRenderer::render before prepare");
    if (inImage)
        target.resize(tile.imageWidth, tile.imageHeight);
    else
        target.resize(tile.width, tile.height);
    const GLuint p = program_.id();
    glUseProgram(p);

    // Parameters: every node's values by the locations found at compile time.
    size_t k = 0;
    auto upload = [&](const PlaneNode& n) {
        for (size_t i = 0; i < n.values.size(); ++i)
            if (paramLocations_[k][i] >= 0) glUniform1f(paramLocations_[k][i], float(n.values[i].x));
        ++k;
    };
    for (const PlaneNode& n : formula.start) upload(n);
    for (const PlaneNode& n : formula.nodes) upload(n);
    upload(formula.estimator);
    glUniform1i(at_.iterations, formula.iterations);
    glUniform1f(at_.bailout, float(formula.bailout));

    const double pixelSize = view.pixelSize(tile.imageWidth);
    if (double_) {
        glUniform2d(at_.center, view.center.x, view.center.y);
        glUniform1d(at_.pixelSize, pixelSize);
    } else {
        glUniform2f(at_.center, float(view.center.x), float(view.center.y));
        glUniform1f(at_.pixelSize, float(pixelSize));
    }
    glUniform2i(at_.imageSize, tile.imageWidth, tile.imageHeight);
    glUniform2i(at_.tileOrigin, tile.x0, tile.y0);
    glUniform2i(at_.tileSize, tile.width, tile.height);
    glUniform2i(at_.storeOrigin, inImage ? tile.x0 : 0, inImage ? tile.y0 : 0);
    glUniform1i(at_.sampleBegin, sampleBegin);
    glUniform1i(at_.sampleCount, sampleCount);
    glUniform1i(at_.accumulate, accumulate ? 1 : 0);
    auto vec = [](GLint location, const vec3& v) { glUniform3f(location, float(v.x), float(v.y), float(v.z)); };
    vec(at_.paletteA, colouring.paletteA);
    vec(at_.paletteB, colouring.paletteB);
    vec(at_.paletteC, colouring.paletteC);
    vec(at_.paletteD, colouring.paletteD);
    vec(at_.interior, colouring.interior);
    glUniform1f(at_.paletteFrequency, float(colouring.frequency));
    glUniform1f(at_.paletteOffset, float(colouring.offset));
    glUniform1f(at_.edgeWidth, float(colouring.edgeWidth));

    glBindImageTexture(0, target.colourTexture(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    glBindImageTexture(1, target.aovTexture(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
    gl::dispatchOver(p, tile.width, tile.height);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
}

PlaneTileData readPlaneTarget(const PlaneTarget& target) {
    PlaneTileData d;
    d.width = target.width();
    d.height = target.height();
    const size_t n = size_t(d.width) * size_t(d.height) * 4;
    d.colour.resize(n);
    d.aov.resize(n);
    const GLsizei bytes = GLsizei(n * sizeof(float));
    glGetTextureImage(target.colourTexture(), 0, GL_RGBA, GL_FLOAT, bytes, d.colour.data());
    glGetTextureImage(target.aovTexture(), 0, GL_RGBA, GL_FLOAT, bytes, d.aov.data());
    return d;
}

}  // namespace fraktal
