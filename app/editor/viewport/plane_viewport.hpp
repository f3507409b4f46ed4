// The editor's 2D viewport: core/plane/plane_view.hpp's progressive PlaneView (sums of linear
// Rec.709 samples, count in alpha) shown through the same OCIO display pass, exposure and view
// as the 3D viewport (ocio_display_pass.hpp), with the division by the sample count and the
// conversion to the working space done there. Needs the editor's current GL context.
#pragma once

#include <epoxy/gl.h>

#include <chrono>
#include <optional>
#include <string>

#include "app/editor/viewport/display_target.hpp"
#include "app/editor/viewport/ocio_display_pass.hpp"
#include "core/color/color_pipeline.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_view.hpp"

namespace fraktal::editor {

// What the 2D stats overlay shows.
struct PlaneViewportStats {
    int samples = 0, target = 0;  // samples per pixel done, and where refinement stops
    int width = 0, height = 0;
    double passMs = 0.0;  // wall time of the last refinement pass (0 when it did none)
    bool fp64 = false;    // the program runs in double precision
};

class PlaneViewport {
   public:
    // `color` is owned by the caller and outlives the view.
    explicit PlaneViewport(const ColorPipeline& color) : color_(color) {}
    PlaneViewport(const PlaneViewport&) = delete;
    PlaneViewport& operator=(const PlaneViewport&) = delete;

    // Follows the preset (formula, colouring, view rectangle: any change restarts refinement),
    // renders the next refinement pass for a viewport of this size and refreshes
    // displayTexture() (smaller than asked while the view moves: the caller stretches it). A
    // GLSL error keeps the last good image (compileError() names the node).
    void render(const PlanePreset& preset, int width, int height);
    // Refinement stops at this many samples per pixel (the thumbnails want few).
    void setTargetSamples(int samples) { view_.refinement().target = samples; }
    // Whether a moving view renders at a reduced size (on for the editor's view; off where the
    // image must have the size asked, the thumbnails).
    void setReducedWhileMoving(bool on) { reducedWhileMoving_ = on; }
    // A frame renders as much of a refinement pass as fits in about this time (at least a row
    // of one sample), so that the editor stays responsive while the image refines on a CPU
    // renderer.
    static constexpr double kPassBudgetMs = 60.0;
    static constexpr int kMaxSamplesPerPass = 8;
    static constexpr double kRestSeconds = 0.3;

    GLuint displayTexture() const { return display_.texture(); }  // RGBA8, top row first
    bool refining() const { return view_.refining(); }
    const PlaneViewportStats& stats() const { return stats_; }
    const std::vector<std::string>& warnings() const { return view_.warnings(); }
    const std::string& compileError() const { return compileError_; }
    const std::string& displayError() const { return displayError_; }

   private:
    void redisplay(const PlanePreset& preset);

    const ColorPipeline& color_;
    PlaneView view_;
    OcioDisplayPass pass_;
    DisplayTarget display_;
    std::string compileError_, displayError_;
    std::string failedStructure_;  // a structure whose compile failed: not retried every frame
    std::optional<std::pair<std::string, mat3>> toWorking_;  // cache of planeWorkingFromRec709
    bool imageChanged_ = false;
    std::optional<std::pair<DisplayKey, double>> shownDisplay_;
    PlaneViewportStats stats_;
    bool reducedWhileMoving_ = true;
    double msPerPixelSample_ = 0.0;  // what one sample of one pixel cost in the last pass
    // When the formula, colouring or view last changed: until it rests for kRestSeconds the view
    // renders at a reduced size (planeInteractiveScale) so that dragging stays fluid.
    std::optional<std::chrono::steady_clock::time_point> lastChange_;
};

// Whether two view rectangles are the same (the view restarts refinement only on a change).
inline bool sameRect(const PlaneViewRect& a, const PlaneViewRect& b) {
    return a.center == b.center && a.width == b.width;
}

}  // namespace fraktal::editor
