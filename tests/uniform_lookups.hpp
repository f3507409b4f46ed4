// A counting stand-in for glGetUniformLocation, for tests that a frame or a draw looks up no
// uniform locations by name.
#pragma once

#include <epoxy/gl.h>

#include <chrono>

namespace fraktal::test {

// Stands in for libepoxy's glGetUniformLocation (a function pointer) and counts the lookups and
// the time they take.
struct UniformLookups {
    static inline PFNGLGETUNIFORMLOCATIONPROC real = nullptr;
    static inline int calls = 0;
    static inline double seconds = 0.0;
    static GLint EPOXY_CALLSPEC counted(GLuint program, const GLchar* name) {
        ++calls;
        const auto start = std::chrono::steady_clock::now();
        const GLint location = real(program, name);
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return location;
    }
    UniformLookups() {
        real = epoxy_glGetUniformLocation;
        epoxy_glGetUniformLocation = &counted;
        calls = 0;
        seconds = 0.0;
    }
    ~UniformLookups() { epoxy_glGetUniformLocation = real; }
};

}  // namespace fraktal::test
