// The GL still renderer: renders one tile of an image per call into an ImageStrip, through
// shaders/still.frag (camera rays, shaders/march.glsl, shaders/shade.glsl). Needs a current GL
// 4.5 context (gl::HeadlessContext on the command line).
#pragma once

#include <epoxy/gl.h>

#include <string>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/gl/camera_uniforms.hpp"
#include "core/gl/formula_uniforms.hpp"
#include "core/gl/program.hpp"
#include "core/image/image_strip.hpp"
#include "core/render/shading_uniforms.hpp"
#include "core/render/tiles.hpp"
#include "core/shading_params.hpp"

namespace fraktal::gl {

class StillRenderer {
   public:
    // Compiles the still program for the formula's structure (throws naming the node on a GLSL
    // error) and allocates render targets of tileSize x tileSize.
    StillRenderer(const Formula& formula, int tileSize);
    ~StillRenderer();
    StillRenderer(const StillRenderer&) = delete;
    StillRenderer& operator=(const StillRenderer&) = delete;

    // Sets everything that stays the same across the tiles of one image. `formula` must have the
    // constructor's structure.
    // adaptiveTolerance: see shaders/still.frag (0: every pixel takes render.spp samples).
    // lens: depth of field (shaders/lens.glsl); the default is a pinhole.
    void setScene(const Formula& formula, const Camera& camera, const RenderSettings& render,
                  const ShadingParams& shading, double adaptiveTolerance = 0.0, const ThinLens& lens = {});
    // Renders `tile` (which must lie in `strip`'s rows and be at most tileSize square).
    void renderTile(const TileRect& tile, ImageStrip& strip);

    int tileSize() const { return tileSize_; }
    // The linked program (the portability checks read it).
    const Program& program() const { return program_; }

   private:
    std::string structure_;
    int tileSize_;
    Program program_;
    FormulaUniforms formulaUniforms_;
    ShadingUniforms shadingUniforms_;
    // Uniform locations, looked up once when the program is built: setScene runs per frame of a
    // sequence, renderTile per tile.
    struct Locations {
        CameraLocations camera;
        LensLocations lens;
        GLint tileOrigin = -1, imageSize = -1, spp = -1, maxSteps = -1, filterRadius = -1, transparentBackground = -1,
              adaptiveTolerance = -1, filterInverseCdf = -1;
    } at_;
    GLuint framebuffer_ = 0, vertexArray_ = 0;
    GLuint targets_[4] = {0, 0, 0, 0};
    int imageWidth_ = 0, imageHeight_ = 0;
};

}  // namespace fraktal::gl
