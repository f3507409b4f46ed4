// Evaluates a formula's generated GLSL at given points on the current GL context.
#pragma once

#include <span>
#include <vector>

#include "core/de_check.hpp"
#include "core/formula.hpp"
#include "core/gl/formula_uniforms.hpp"
#include "core/gl/program.hpp"

namespace fraktal::gl {

struct GpuSample {
    float distance;
    int iterations;
    bool escaped;
    glm::vec4 trap;
    int surface;  // Evaluation::surface
};

class DEProbe {
   public:
    // Compiles the probe for the formula's structure; throws on a GLSL error (naming the node).
    explicit DEProbe(const Formula& formula);
    ~DEProbe();
    DEProbe(const DEProbe&) = delete;
    DEProbe& operator=(const DEProbe&) = delete;

    // `formula` may differ from the constructor's in values only (same structureKey()).
    std::vector<GpuSample> evaluate(const Formula& formula, std::span<const vec3> points);
    // The linked program (the portability checks read it).
    const Program& program() const { return program_; }

   private:
    std::string structure_;
    Program program_;
    FormulaUniforms uniforms_;
    GLint countLocation_ = -1;  // looked up once: evaluate runs per batch of points
    GLuint buffers_[2] = {0, 0};
};

// The formula's samples taken on the GL context: how checks and tools evaluate formulas with
// custom GLSL blocks, which have no CPU body. Single precision.
class GpuSampler final : public FormulaSampler {
   public:
    explicit GpuSampler(const Formula& f) : formula_(f), probe_(f) {}
    const Formula& formula() const override { return formula_; }
    void evaluate(std::span<const vec3> points, std::span<Evaluation> out) override;

   private:
    const Formula& formula_;
    DEProbe probe_;
};

}  // namespace fraktal::gl
