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
gl::Program compileViewportPass(const char* name, const char* defines = "") {
    const GeneratedFormula none;
    return gl::compileCompute(assembleShader(none, name, concat({"viewport_common.glsl", name}), defines));
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
    const std::initializer_list<const char*> resume = {"march.glsl", "shade.glsl", "viewport_common.glsl",
                                                       "viewport_march.comp"};
    march = compileFormulaPass(f, g, "viewport_march.comp", "#define START 0\n#define FROM_LIST 0", resume);
    marchFromList = compileFormulaPass(f, g, "viewport_march.comp", "#define START 0\n#define FROM_LIST 1", resume);
    marchFromStart = compileFormulaPass(
        f, g, "viewport_march.comp", "#define START 1\n#define FROM_LIST 0",
        {"march.glsl", "shade.glsl", "viewport_common.glsl", "viewport_start.glsl", "viewport_march.comp"});
    shade = compileFormulaPass(f, g, "viewport_shade.comp", "",
                               {"march.glsl", "shade.glsl", "viewport_common.glsl", "viewport_shade.comp"});
    cone = compileFormulaPass(f, g, "viewport_cone.comp", "",
                              {"march.glsl", "viewport_common.glsl", "viewport_cone.comp"});
    accumulateAtRest = compileViewportPass("viewport_accumulate.comp", "#define AT_REST 1");
    accumulateMoving = compileViewportPass("viewport_accumulate.comp", "#define AT_REST 0");
    resolve = compileViewportPass("viewport_resolve.comp");
    listGroups = compileViewportPass("viewport_list_groups.comp");
    reprojectClaim = compileViewportPass("viewport_reproject.comp", "#define CLAIM 1");
    reprojectWrite = compileViewportPass("viewport_reproject.comp", "#define CLAIM 0");
    const GeneratedFormula none;
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
