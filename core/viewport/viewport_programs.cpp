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

FormulaProgram compileFormulaPass(const Formula& f, const GeneratedFormula& g, const char* name, const char* defines,
                                  std::initializer_list<const char*> sources) {
    FormulaProgram p;
    p.program = gl::compileCompute(assembleShader(g, name, concat(sources), defines));
    p.formula = gl::FormulaUniforms(p.program.id(), f);
    p.shading = gl::ShadingUniforms(p.program.id());
    return p;
}

}  // namespace

void FormulaProgram::use(const Formula& f, const ShadingParams& params) const {
    glUseProgram(program.id());
    formula.upload(f);
    shading.upload(params);
}

ViewportPrograms::ViewportPrograms(const Formula& f) : structure(f.structureKey()) {
    const GeneratedFormula g = generateFormulaGLSL(f);
    march = compileFormulaPass(f, g, "viewport_march.comp", "#define START 0",
                               {"march.glsl", "shade.glsl", "viewport_common.glsl", "viewport_march.comp"});
    marchFromStart = compileFormulaPass(
        f, g, "viewport_march.comp", "#define START 1",
        {"march.glsl", "shade.glsl", "viewport_common.glsl", "viewport_start.glsl", "viewport_march.comp"});
    shade = compileFormulaPass(f, g, "viewport_shade.comp", "",
                               {"march.glsl", "shade.glsl", "viewport_common.glsl", "viewport_shade.comp"});
    cone = compileFormulaPass(f, g, "viewport_cone.comp", "",
                              {"march.glsl", "viewport_common.glsl", "viewport_cone.comp"});
    const GeneratedFormula none;
    const std::string accumulate = concat({"viewport_common.glsl", "viewport_accumulate.comp"});
    accumulateAtRest =
        gl::compileCompute(assembleShader(none, "viewport_accumulate.comp", accumulate, "#define AT_REST 1"));
    accumulateMoving =
        gl::compileCompute(assembleShader(none, "viewport_accumulate.comp", accumulate, "#define AT_REST 0"));
    resolve = gl::compileCompute(
        assembleShader(none, "viewport_resolve.comp", concat({"viewport_common.glsl", "viewport_resolve.comp"})));
    const std::string reproject = concat({"viewport_common.glsl", "viewport_reproject.comp"});
    reprojectClaim = gl::compileCompute(assembleShader(none, "viewport_reproject.comp", reproject, "#define CLAIM 1"));
    reprojectWrite = gl::compileCompute(assembleShader(none, "viewport_reproject.comp", reproject, "#define CLAIM 0"));
    display = gl::compileGraphics(assembleShader(none, "fullscreen.vert", concat({"fullscreen.vert"})),
                                  assembleShader(none, "viewport_display.frag", concat({"viewport_display.frag"})));
}

void setInt(GLuint program, const char* name, int value) { glUniform1i(glGetUniformLocation(program, name), value); }
void setFloat(GLuint program, const char* name, float value) {
    glUniform1f(glGetUniformLocation(program, name), value);
}

void setViewUniforms(GLuint program, const Camera& camera, int width, int height) {
    gl::setCameraUniforms(program, camera);
    glUniform2i(glGetUniformLocation(program, "u_size"), width, height);
    setFloat(program, "u_pixelAngle", float(camera.pixelAngle(height)));
}

}  // namespace fraktal::viewport
