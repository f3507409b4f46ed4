// Compiling and linking GL programs from assembled sources, with errors that name the node.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "core/glsl_gen.hpp"

namespace fraktal::gl {

// One shader stage's source as the driver compiled it.
struct StageSource {
    GLenum stage;  // GL_COMPUTE_SHADER, GL_VERTEX_SHADER, GL_FRAGMENT_SHADER
    std::string text;
};

// An owned GL program object, with its name and the sources it was linked from (so that a test
// can hand every program fraktal links to glslang, and check its resources: portable_limits.hpp).
class Program {
   public:
    Program() = default;
    Program(GLuint id, std::string name, std::vector<StageSource> stages)
        : id_(id), name_(std::move(name)), stages_(std::move(stages)) {}
    ~Program() { reset(); }
    Program(Program&& o) noexcept : id_(o.id_), name_(std::move(o.name_)), stages_(std::move(o.stages_)) { o.id_ = 0; }
    Program& operator=(Program&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = o.id_;
            name_ = std::move(o.name_);
            stages_ = std::move(o.stages_);
            o.id_ = 0;
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset();
    // The program's name as errors give it: its main template, and its variant's defines.
    const std::string& name() const { return name_; }
    const std::vector<StageSource>& stages() const { return stages_; }

   private:
    GLuint id_ = 0;
    std::string name_;
    std::vector<StageSource> stages_;
};

// Dispatches a 2D compute program (in use) over width x height invocations, in work groups of
// the size its shader declares (local_size_x/y).
void dispatchOver(GLuint program, int width, int height);

// Throws std::runtime_error with the driver's log, rewritten to name nodes, or naming the resource
// where the linked program needs more than every OpenGL 4.5 driver provides (portable_limits.hpp).
Program compileCompute(const ShaderSource& source);
Program compileGraphics(const ShaderSource& vertex, const ShaderSource& fragment);

}  // namespace fraktal::gl
