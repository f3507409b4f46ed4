// Uploads ShadingParams to the uniforms that shaders/march.glsl and shaders/shade.glsl declare.
// Locations are looked up once, when the program is built; a uniform the compiler removed is
// skipped (-1).
#pragma once

#include <epoxy/gl.h>

#include <vector>

#include "core/shading_params.hpp"

namespace fraktal::gl {

class ShadingUniforms {
   public:
    ShadingUniforms() = default;
    explicit ShadingUniforms(GLuint program);
    // Sets the values on the currently bound program.
    void upload(const ShadingParams& params) const;

   private:
    std::vector<GLint> locations_;  // in the order of the uniforms' list (shading_uniforms.cpp)
};

}  // namespace fraktal::gl
