// The viewport's display pass: scene-linear image -> exposure -> the OCIO display/view transform
// -> display-referred RGBA8, on the GPU. The same transform as the still export's PNG
// (fraktal::DisplayTransform, core/color/color_pipeline.hpp): exposure in stops applied in the
// working space, then the processor for DisplayViewTransform(working space, display, view). The
// GLSL comes from OpenColorIO itself (GpuShaderDesc, GLSL 4.0) with its LUT textures, so any
// $OCIO config works, not only the shipped one. Data stays linear until here (tev style).
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "core/color/color_pipeline.hpp"
#include "core/gl/program.hpp"
#include "core/vec.hpp"

namespace fraktal::editor {

// What the pass's program depends on: a change rebuilds it. Exposure is a uniform.
struct DisplayKey {
    std::string workingSpace, display, view;
    bool operator==(const DisplayKey&) const = default;
};

class OcioDisplayPass {
   public:
    OcioDisplayPass();
    ~OcioDisplayPass();
    OcioDisplayPass(const OcioDisplayPass&) = delete;
    OcioDisplayPass& operator=(const OcioDisplayPass&) = delete;

    // Builds the program for `key` unless it already has it. Throws std::runtime_error naming the
    // config and what is wrong (unknown space, display or view; a shader that does not compile);
    // the previous program stays usable.
    void configure(const ColorPipeline& color, const DisplayKey& key);
    bool configured() const { return bool(program_); }
    // The linked program (the portability checks read it).
    const gl::Program& program() const { return program_; }
    const DisplayKey& key() const { return key_; }

    // Draws `linearImage` (RGBA32F, scene-linear in the working space) into the bound framebuffer
    // at the current glViewport, texel for pixel (same size, same row order).
    void draw(GLuint linearImage, double exposureStops) const { draw(linearImage, exposureStops, {}); }
    // The 2D view's image (core/plane/plane_view.hpp) is progressive sums of linear Rec.709
    // samples with their count in alpha: shown as toWorking * (rgb / a).
    struct SumInput {
        bool divideByCount = false;
        mat3 toWorking{1.0};  // linear Rec.709 -> working space (identity: already in it)
    };
    void draw(GLuint linearImage, double exposureStops, const SumInput& input) const;

   private:
    struct LutTexture {
        GLuint id = 0;
        GLenum target = GL_TEXTURE_2D;
        std::string sampler;
    };
    void releaseLuts();

    gl::Program program_;
    std::vector<LutTexture> luts_;
    GLint gainLocation_ = -1, divideByCountLocation_ = -1, toWorkingLocation_ = -1;  // looked up once, as above
    DisplayKey key_;
    GLuint emptyVertexArray_ = 0;
};

}  // namespace fraktal::editor
