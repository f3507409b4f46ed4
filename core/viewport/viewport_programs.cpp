#include "core/viewport/viewport_programs.hpp"

#include <glm/gtc/type_ptr.hpp>

#include "core/shader_library.hpp"

namespace fraktal::viewport {

namespace {

std::string concat(std::initializer_list<const char*> names) {
    std::string text;
    for (const char* n : names) {
        text += shaderTemplate(n);
        text += '\n';
    }
    return text;
}

// A compute pass without the formula, from viewport_common.glsl and its own file.
gl::Program compileViewportProgram(const char* name, const char* defines = "") {
    const GeneratedFormula none;
    return gl::compileCompute(
        assembleShader(none, name, concat({"camera.glsl", "lens.glsl", "viewport_common.glsl", name}), defines));
}

Pass withUniforms(gl::Program program) {
    Pass p{std::move(program), {}, {}};
    p.uniforms = PassUniforms(p.program.id());
    p.images = PassImages(p.program);
    return p;
}

Pass compileViewportPass(const char* name, const char* defines = "") {
    return withUniforms(compileViewportProgram(name, defines));
}

FormulaProgram compileFormulaPass(const Formula& f, const GeneratedFormula& g, const char* name, const char* defines,
                                  std::initializer_list<const char*> sources) {
    FormulaProgram p;
    p.program = gl::compileCompute(assembleShader(g, name, concat(sources), defines));
    p.uniforms = PassUniforms(p.program.id());
    p.images = PassImages(p.program);
    p.formula = gl::FormulaUniforms(p.program.id(), f);
    p.shading = gl::ShadingUniforms(p.program.id());
    return p;
}

}  // namespace

PassUniforms::PassUniforms(GLuint program)
    : camera(program),
      newCamera(program, {"u_newCameraPosition", "u_newRight", "u_newUp", "u_newForward", "u_newTanHalfFovY",
                          "u_newHalfFovY", "u_newProjection"}),
      lens(program) {
    const auto at = [program](const char* name) { return glGetUniformLocation(program, name); };
    size = at("u_size");
    pixelAngle = at("u_pixelAngle");
    newSize = at("u_newSize");
    block = at("u_block");
    stepsPerFrame = at("u_stepsPerFrame");
    maxSteps = at("u_maxSteps");
    atRest = at("u_atRest");
    maxCarryFrames = at("u_maxCarryFrames");
    coarseHits = at("u_coarseHits");
    deferAfter = at("u_deferAfter");
    resetAll = at("u_resetAll");
    sliceCount = at("u_sliceCount");
    sliceIndex = at("u_sliceIndex");
    generation = at("u_generation");
    coneTile = at("u_coneTile");
    coneSteps = at("u_coneSteps");
    maxSamples = at("u_maxSamples");
    initialOmega = at("u_initialOmega");
    radius = at("u_radius");
    exposure = at("u_exposure");
    flipY = at("u_flipY");
}

void Pass::use(const MarchState& state) const {
    glUseProgram(program.id());
    images.bind(state);
}

void FormulaProgram::use(const MarchState& state, const Formula& f, const ShadingParams& params) const {
    glUseProgram(program.id());
    images.bind(state);
    formula.upload(f);
    shading.upload(params);
}

ViewportPrograms::ViewportPrograms(const Formula& f) : structure(f.structureKey()) {
    const GeneratedFormula g = generateFormulaGLSL(f);
    const std::initializer_list<const char*> resume = {"march.glsl", "shade.glsl",           "camera.glsl",
                                                       "lens.glsl",  "viewport_common.glsl", "viewport_march.comp"};
    march = compileFormulaPass(f, g, "viewport_march.comp", "#define START 0\n#define FROM_LIST 0", resume);
    marchFromList = compileFormulaPass(f, g, "viewport_march.comp", "#define START 0\n#define FROM_LIST 1", resume);
    const std::initializer_list<const char*> start = {
        "march.glsl",           "shade.glsl",          "camera.glsl",        "lens.glsl",
        "viewport_common.glsl", "viewport_start.glsl", "viewport_march.comp"};
    marchFromStart = compileFormulaPass(f, g, "viewport_march.comp", "#define START 1\n#define FROM_LIST 0", start);
    shade = compileFormulaPass(
        f, g, "viewport_shade.comp", "",
        {"march.glsl", "shade.glsl", "camera.glsl", "lens.glsl", "viewport_common.glsl", "viewport_shade.comp"});
    cone = compileFormulaPass(f, g, "viewport_cone.comp", "",
                              {"march.glsl", "camera.glsl", "lens.glsl", "viewport_common.glsl", "viewport_cone.comp"});
    accumulateAtRest = compileViewportPass("viewport_accumulate.comp", "#define AT_REST 1");
    accumulateMoving = compileViewportPass("viewport_accumulate.comp", "#define AT_REST 0");
    resolve = compileViewportPass("viewport_resolve.comp");
    listGroups = compileViewportProgram("viewport_list_groups.comp");
    reprojectClaim = compileViewportPass("viewport_reproject.comp", "#define CLAIM 1\n#define BLOCK 0");
    reprojectWrite = compileViewportPass("viewport_reproject.comp", "#define CLAIM 0\n#define BLOCK 0");
    reprojectBlockClaim = compileViewportPass("viewport_reproject.comp", "#define CLAIM 1\n#define BLOCK 1");
    reprojectBlockWrite = compileViewportPass("viewport_reproject.comp", "#define CLAIM 0\n#define BLOCK 1");
    const GeneratedFormula none;
    display = withUniforms(
        gl::compileGraphics(assembleShader(none, "fullscreen.vert", concat({"fullscreen.vert"})),
                            assembleShader(none, "viewport_display.frag", concat({"viewport_display.frag"}))));
}

std::vector<const gl::Program*> ViewportPrograms::all() const {
    return {&march.program,
            &marchFromStart.program,
            &marchFromList.program,
            &shade.program,
            &cone.program,
            &accumulateAtRest.program,
            &accumulateMoving.program,
            &resolve.program,
            &display.program,
            &listGroups,
            &reprojectClaim.program,
            &reprojectWrite.program,
            &reprojectBlockClaim.program,
            &reprojectBlockWrite.program};
}

void setViewUniforms(const PassUniforms& at, const Camera& camera, int width, int height, const ThinLens& lens) {
    gl::setCameraUniforms(at.camera, camera);
    gl::setLensUniforms(at.lens, lens, camera);
    glUniform2i(at.size, width, height);
    glUniform1f(at.pixelAngle, float(camera.pixelAngle(height, width)));
}

}  // namespace fraktal::viewport
