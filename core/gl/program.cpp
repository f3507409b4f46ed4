#include "core/gl/program.hpp"

#include <stdexcept>
#include <vector>

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

Program link(const std::vector<GLuint>& shaders, const std::string& name) {
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
    return Program(program);
}

}  // namespace

void Program::reset() {
    if (id_) glDeleteProgram(id_);
    id_ = 0;
}

Program compileCompute(const ShaderSource& source) {
    return link({compileStage(GL_COMPUTE_SHADER, source)}, source.programName);
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
    return link({vs, fs}, fragment.programName);
}

void dispatchOver(GLuint program, int width, int height) {
    GLint group[3] = {1, 1, 1};
    glGetProgramiv(program, GL_COMPUTE_WORK_GROUP_SIZE, group);
    glDispatchCompute(GLuint((width + group[0] - 1) / group[0]), GLuint((height + group[1] - 1) / group[1]), 1);
}

}  // namespace fraktal::gl
