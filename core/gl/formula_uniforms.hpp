// Uploads a formula's parameter values to the uniforms its generated GLSL declares. Locations
// are looked up once per program; setting values never recompiles.
#pragma once

#include <epoxy/gl.h>

#include <vector>

#include "core/formula.hpp"

namespace fraktal::gl {

class FormulaUniforms {
   public:
    FormulaUniforms() = default;
    // `formula` must have the structure the program was generated from.
    FormulaUniforms(GLuint program, const Formula& formula);
    // Sets the values on the currently bound program.
    void upload(const Formula& formula) const;

   private:
    GLint iterations_ = -1, bailout_ = -1, deFactor_ = -1, boundRadius_ = -1;
    std::vector<std::vector<GLint>> nodes_;  // [node][param]; the estimator last
    struct ObjectLocations {
        GLint center = -1, turn = -1;
        std::vector<GLint> params;
    };
    std::vector<ObjectLocations> objects_;
};

}  // namespace fraktal::gl
