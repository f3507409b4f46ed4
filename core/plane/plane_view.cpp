#include "core/plane/plane_view.hpp"

namespace fraktal {

void PlaneView::setPreset(const PlanePreset& preset) {
    // The view rectangle belongs to the user's navigation; the preset's own is taken only when
    // a different preset (by formula and colouring) arrives.
    PlanePreset withoutView = preset;
    withoutView.view = PlaneViewRect{};
    const std::string key = serializePlanePreset(withoutView);
    if (key == presetKey_) return;
    if (presetKey_.empty()) rect_ = preset.view;
    preset_ = preset;
    presetKey_ = key;
    restart();
}

void PlaneView::setRect(const PlaneViewRect& rect) {
    rect_ = rect;
    restart();
}

void PlaneView::pan(double dxPixels, double dyPixels) {
    if (width_ <= 0) return;
    setRect(planePanned(rect_, width_, dxPixels, dyPixels));
}

void PlaneView::zoomAt(double cursorX, double cursorY, double factor) {
    if (width_ <= 0 || factor <= 0.0) return;
    setRect(planeZoomedAt(rect_, width_, height_, cursorX, cursorY, factor));
}

bool PlaneView::update(int width, int height, int maxRows) {
    lastPixelSamples_ = 0.0;
    if (width <= 0 || height <= 0 || presetKey_.empty()) return false;
    if (width != width_ || height != height_) {
        width_ = width;
        height_ = height;
        restart();
    }
    if (passRow_ == 0) {
        passSamples_ = refinement_.nextPassSamples();
        if (passSamples_ == 0) return false;
    }
    renderer_.prepare(preset_.formula);
    const int rows = std::clamp(maxRows, 1, height - passRow_);
    const PlaneTile band{width, height, 0, passRow_, width, rows};
    const int done = refinement_.samplesDone;
    renderer_.render(preset_.formula, preset_.colouring, rect_, band, target_, done, passSamples_, done > 0,
                     /*inImage=*/true);
    lastPixelSamples_ = double(width) * rows * passSamples_;
    passRow_ += rows;
    if (passRow_ >= height) {
        refinement_.samplesDone += passSamples_;
        passRow_ = 0;
    }
    return true;
}

}  // namespace fraktal
