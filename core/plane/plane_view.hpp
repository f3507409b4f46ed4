// The editor's 2D view, as a small class the editor owns: it keeps the view rectangle (pan by
// drag, zoom by wheel about the cursor), the GL textures, and progressive refinement: every
// frame adds a few samples per pixel while nothing changes, and starts afresh when the preset or
// the view does. Needs the editor's current GL context.
//
// What the editor calls, per frame:
//   view.setPreset(preset);                    // after any edit (cheap when nothing changed)
//   view.pan(dx, dy) / view.zoomAt(x, y, f);    // on drag / wheel (pixels from the top left)
//   view.update(width, height);                // renders the next refinement pass
//   ImGui::Image(view.colourTexture(), ...)   // shows colour sums / count (see colourTexture)
#pragma once

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_renderer.hpp"

namespace fraktal {

// Progressive refinement schedule, pure logic: how many samples the next pass adds. The first
// pass is one sample (an instant preview), then doubling passes up to `maxPerPass` until
// `target` samples are reached.
struct PlaneRefinement {
    int samplesDone = 0;
    int target = 64;
    int maxPerPass = 8;

    void restart() { samplesDone = 0; }
    bool finished() const { return samplesDone >= target; }
    int nextPassSamples() const {
        if (finished()) return 0;
        return std::min(target - samplesDone, std::min(maxPerPass, std::max(1, samplesDone)));
    }
};

// How many samples per pixel a pass may add so that it takes about `budgetMs`, given what a
// sample per pixel cost in the last pass (0: not measured yet, the cap applies); at least 1, at
// most `cap`. The editor keeps its frames responsive with it on a slow (CPU) GL driver.
inline int planeSamplesForBudget(double msPerSample, double budgetMs, int cap) {
    if (msPerSample <= 0.0) return cap;
    return std::clamp(int(budgetMs / msPerSample), 1, std::max(1, cap));
}

// The share of the width and height to render at while the user drags or zooms, so that one
// sample of the whole image takes about `budgetMs` (the cost per pixel and sample measured in
// the last pass; 0: not measured, full size); within [minScale, 1]. Refinement at full size
// resumes once the view rests.
inline double planeInteractiveScale(double msPerPixelSample, int width, int height, double budgetMs,
                                    double minScale = 0.25) {
    const double fullMs = msPerPixelSample * double(width) * double(height);
    if (fullMs <= budgetMs) return 1.0;
    return std::clamp(std::sqrt(budgetMs / fullMs), minScale, 1.0);
}

class PlaneView {
   public:
    void setPreset(const PlanePreset& preset);  // restarts refinement when formula or colouring changed
    const PlaneViewRect& rect() const { return rect_; }
    void setRect(const PlaneViewRect& rect);
    void pan(double dxPixels, double dyPixels);
    void zoomAt(double cursorX, double cursorY, double factor);  // factor > 1 zooms in

    // Renders the next pass at this size (a size change restarts), or at most `maxRows` rows of
    // it: a pass then spans several calls, band after band from the top, so that no call takes
    // long on a slow driver (each pixel's alpha counts its own samples, so a half-done pass
    // displays correctly). Returns true when it drew. Throws std::runtime_error on a GLSL error
    // (naming the node).
    bool update(int width, int height, int maxRows = 1 << 30);
    bool refining() const { return !refinement_.finished(); }
    int samples() const { return refinement_.samplesDone; }  // complete passes only
    // Pixel-samples the last update() rendered (its cost measure); 0 when it drew nothing.
    double lastPixelSamples() const { return lastPixelSamples_; }

    // RGBA32F: rgb = sum of linear colours, a = sample count: display rgb / a (the editor's
    // display pass applies exposure and the OCIO view, tev style).
    GLuint colourTexture() const { return target_.colourTexture(); }
    // RGBA32F AOV sums (see PlaneTileData): inside count, iteration and distance sums, outside count.
    GLuint aovTexture() const { return target_.aovTexture(); }
    const std::vector<std::string>& warnings() const { return renderer_.warnings(); }
    PlaneRefinement& refinement() { return refinement_; }
    const PlaneRefinement& refinement() const { return refinement_; }
    bool usesDouble() const { return renderer_.usesDouble(); }

   private:
    PlanePreset preset_;
    std::string presetKey_;
    PlaneViewRect rect_;
    int width_ = 0, height_ = 0;
    PlaneRenderer renderer_;
    PlaneTarget target_;
    PlaneRefinement refinement_;
    int passRow_ = 0;      // the next band of the pass in progress (0: none in progress)
    int passSamples_ = 0;  // the samples per pixel of the pass in progress
    double lastPixelSamples_ = 0.0;

    void restart() {
        refinement_.restart();
        passRow_ = 0;
    }
};

}  // namespace fraktal
