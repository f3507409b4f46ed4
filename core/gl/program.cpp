#include "core/gl/program.hpp"

#include <stdexcept>
#include <vector>

#include "core/gl/portable_limits.hpp"

namespace fraktal::gl {

namespace {

std::string shaderLog(GLuint shader) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::string log(size_t(std::max(length, 1)), '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    return log.c_str();
}

GLuint compileStage(GLenum stage, const ShaderSource& source) {
    GLuint shader = glCreateShader(stage);
    const char* text = source.text.c_str();
    glShaderSource(shader, 1, &text, nullptr);
    glCompileShader(shader);
    GLint ok = 0;
    glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
    if (!ok) {
        const std::string log = source.explainLog(shaderLog(shader));
        glDeleteShader(shader);
        throw std::runtime_error("GLSL compile error in " + source.programName + ":\n" + log);
    }
    return shader;
}

// "viewport_march.comp (START 1, FROM_LIST 0)": the template and the defines that make its variant.
std::string programNameOf(const ShaderSource& main) {
    std::string variant;
    size_t at = main.text.find('\n');
    while (at != std::string::npos && main.text.compare(at + 1, 8, "#define ") == 0) {
        const size_t end = main.text.find('\n', at + 1);
        if (!variant.empty()) variant += ", ";
        variant += main.text.substr(at + 9, end == std::string::npos ? std::string::npos : end - at - 9);
        at = end;
    }
    return variant.empty() ? main.programName : main.programName + " (" + variant + ")";
}

Program link(const std::vector<GLuint>& shaders, const std::string& name, std::vector<StageSource> stages) {
    GLuint program = glCreateProgram();
    for (GLuint s : shaders) glAttachShader(program, s);
    glLinkProgram(program);
    for (GLuint s : shaders) glDeleteShader(s);
    GLint ok = 0;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (!ok) {
        GLint length = 0;
        glGetProgramiv(program, GL_INFO_LOG_LENGTH, &length);
        std::string log(size_t(std::max(length, 1)), '\0');
        glGetProgramInfoLog(program, length, nullptr, log.data());
        glDeleteProgram(program);
        throw std::runtime_error("GLSL link error in " + name + ":\n" + log.c_str());
    }
    Program linked(program, name, std::move(stages));
    // Refused here rather than on the user's driver: llvmpipe, which the tests run on, gives more
    // than OpenGL 4.5 guarantees, and a driver that gives only the minimum refuses the program.
    const std::vector<std::string> over = portableLimitViolations(linked, LimitScope::LinkTime);
    if (!over.empty()) {
        std::string message = "GL program " + name + " needs more than every OpenGL 4.5 driver provides:";
        for (const std::string& v : over) message += "\n  " + v;
        throw std::runtime_error(message);
    }
    return linked;
}

}  // namespace

void Program::reset() {
    if (id_) glDeleteProgram(id_);
    id_ = 0;
}

Program compileCompute(const ShaderSource& source) {
    return link({compileStage(GL_COMPUTE_SHADER, source)}, programNameOf(source), {{GL_COMPUTE_SHADER, source.text}});
}

Program compileGraphics(const ShaderSource& vertex, const ShaderSource& fragment) {
    GLuint vs = compileStage(GL_VERTEX_SHADER, vertex);
    GLuint fs = 0;
    try {
        fs = compileStage(GL_FRAGMENT_SHADER, fragment);
    } catch (...) {
        glDeleteShader(vs);
        throw;
    }
    return link({vs, fs}, programNameOf(fragment),
                {{GL_VERTEX_SHADER, vertex.text}, {GL_FRAGMENT_SHADER, fragment.text}});
}

void dispatchOver(GLuint program, int width, int height) {
    GLint group[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, group);
    glDispatchCompute(GLuint((width + group[0] - 1) / group[0]), GLuint((height + group[1] - 1) / group[1]), 1);
}

}  // namespace fraktal::gl
