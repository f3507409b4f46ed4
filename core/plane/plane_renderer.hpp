// The 2D GL renderer: runs a 2D formula per sample on the GPU (shaders/plane_render.comp) in
// double precision where the driver has fp64, summing colour and AOVs into a tile's two float
// images. Used by the still export (core/plane/plane_still.hpp) and the editor's 2D view
// (core/plane/plane_view.hpp). Needs a current GL 4.5 context.
#pragma once

#include <epoxy/gl.h>

#include <string>
#include <vector>

#include "core/gl/program.hpp"
#include "core/plane/plane_colouring.hpp"
#include "core/plane/plane_formula.hpp"
#include "core/plane/plane_view_rect.hpp"

namespace fraktal {

enum class PlanePrecision { Auto, Double, Float };

// Whether the current context runs double-precision shaders (GL 4.0 or GL_ARB_gpu_shader_fp64).
bool planeFp64Available();

// Two float images of one tile: colour (rgb sum, sample count) and AOVs (inside count,
// smooth-iteration sum over outside samples, distance sum over outside samples, outside count).
class PlaneTarget {
   public:
    PlaneTarget() = default;
    ~PlaneTarget();
    PlaneTarget(const PlaneTarget&) = delete;
    PlaneTarget& operator=(const PlaneTarget&) = delete;

    void resize(int width, int height);  // keeps the textures when the size is unchanged
    int width() const { return width_; }
    int height() const { return height_; }
    GLuint colourTexture() const { return colour_; }
    GLuint aovTexture() const { return aov_; }

   private:
    GLuint colour_ = 0, aov_ = 0;
    int width_ = 0, height_ = 0;
};

// One tile of the image: pixels [x0, x0 + width) x [y0, y0 + height) of an imageWidth x
// imageHeight image, counted from the top left.
struct PlaneTile {
    int imageWidth = 0, imageHeight = 0;
    int x0 = 0, y0 = 0, width = 0, height = 0;
};

// A tile's summed images read back, and their per-pixel resolve.
struct PlaneTileData {
    int width = 0, height = 0;
    std::vector<float> colour;  // 4 floats per pixel, rows from the top
    std::vector<float> aov;

    size_t at(int x, int y) const { return (size_t(y) * size_t(width) + size_t(x)) * 4; }
    double samples(int x, int y) const { return colour[at(x, y) + 3]; }
    double insideFraction(int x, int y) const { return aov[at(x, y)] / std::max(1.0, samples(x, y)); }
    // Mean over the pixel's outside samples (0 where all were inside).
    double meanIterations(int x, int y) const { return aov[at(x, y) + 1] / std::max(1.0f, aov[at(x, y) + 3]); }
    double meanDistance(int x, int y) const { return aov[at(x, y) + 2] / std::max(1.0f, aov[at(x, y) + 3]); }
    vec3 meanColour(int x, int y) const {
        const size_t i = at(x, y);
        return vec3(colour[i], colour[i + 1], colour[i + 2]) / std::max(1.0, samples(x, y));
    }
};

class PlaneRenderer {
   public:
    // Compiles the formula's program when its structure or the precision changed. Throws
    // std::runtime_error with the driver's log naming the node.
    void prepare(const PlaneFormula& formula, PlanePrecision precision = PlanePrecision::Auto);
    bool usesDouble() const { return double_; }
    // The linked program (the portability checks read it).
    const gl::Program& program() const { return program_; }
    // Why the image may be less precise than asked (no fp64, a non-whole power); each once.
    const std::vector<std::string>& warnings() const { return warnings_; }

    // Adds samples [sampleBegin, sampleBegin + sampleCount) of every pixel of the tile into
    // `target` (sized to the tile); accumulate = false starts the sums afresh. With `inImage`,
    // `target` is the whole image (sized imageWidth x imageHeight) and the tile's pixels land at
    // their place in it (the editor's view renders a pass in bands over several frames).
    void render(const PlaneFormula& formula, const PlaneColouring& colouring, const PlaneViewRect& view,
                const PlaneTile& tile, PlaneTarget& target, int sampleBegin, int sampleCount, bool accumulate,
                bool inImage = false);

   private:
    gl::Program program_;
    std::string key_;
    bool double_ = false;
    std::vector<std::string> warnings_;
    std::vector<std::vector<GLint>> paramLocations_;  // [node][param]: start, loop, estimator
    // The other uniforms' locations, looked up once when the program is built (render runs per
    // band of every frame).
    struct Locations {
        GLint iterations = -1, bailout = -1, center = -1, pixelSize = -1, imageSize = -1, tileOrigin = -1,
              tileSize = -1, storeOrigin = -1, sampleBegin = -1, sampleCount = -1, accumulate = -1;
        GLint paletteA = -1, paletteB = -1, paletteC = -1, paletteD = -1, interior = -1, paletteFrequency = -1,
              paletteOffset = -1, edgeWidth = -1;
    } at_;
};

// Reads a target back (waits for the GPU).
PlaneTileData readPlaneTarget(const PlaneTarget& target);

}  // namespace fraktal
