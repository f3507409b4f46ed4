// Compiling and linking GL programs from assembled sources, with errors that name the node.
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "core/glsl_gen.hpp"

namespace fraktal::gl {

// An owned GL program object.
class Program {
   public:
    Program() = default;
    explicit Program(GLuint id) : id_(id) {}
    ~Program() { reset(); }
    Program(Program&& o) noexcept : id_(o.id_) { o.id_ = 0; }
    Program& operator=(Program&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = o.id_;
            o.id_ = 0;
        }
        return *this;
    }
    GLuint id() const { return id_; }
    explicit operator bool() const { return id_ != 0; }
    void reset();

   private:
    GLuint id_ = 0;
};

// Dispatches a 2D compute program (in use) over width x height invocations, in work groups of
// the size its shader declares (local_size_x/y).
void dispatchOver(GLuint program, int width, int height);

// Throws std::runtime_error with the driver's log, rewritten to name nodes.
Program compileCompute(const ShaderSource& source);
Program compileGraphics(const ShaderSource& vertex, const ShaderSource& fragment);

}  // namespace fraktal::gl
