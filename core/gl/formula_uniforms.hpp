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
    GLint boundRadius_ = -1;
    // One fractal's uniforms (shaders/formula_fractal.glsl): the first, then each combined one.
    struct FractalLocations {
        GLint iterations = -1, bailout = -1, deFactor = -1;
        GLint center = -1, turn = -1, scale = -1, repeat = -1;
        std::vector<std::vector<GLint>> nodes;  // [node][param]; the estimator last
    };
    std::vector<FractalLocations> fractals_;
    struct ObjectLocations {
        GLint center = -1, turn = -1, repeat = -1;
        std::vector<GLint> params;
    };
    std::vector<ObjectLocations> objects_;
};

}  // namespace fraktal::gl
