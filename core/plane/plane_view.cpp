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
    refinement_.restart();
}

void PlaneView::setRect(const PlaneViewRect& rect) {
    rect_ = rect;
    refinement_.restart();
}

void PlaneView::pan(double dxPixels, double dyPixels) {
    if (width_ <= 0) return;
    setRect(planePanned(rect_, width_, dxPixels, dyPixels));
}

void PlaneView::zoomAt(double cursorX, double cursorY, double factor) {
    if (width_ <= 0 || factor <= 0.0) return;
    setRect(planeZoomedAt(rect_, width_, height_, cursorX, cursorY, factor));
}

bool PlaneView::update(int width, int height) {
    if (width <= 0 || height <= 0 || presetKey_.empty()) return false;
    if (width != width_ || height != height_) {
        width_ = width;
        height_ = height;
        refinement_.restart();
    }
    const int count = refinement_.nextPassSamples();
    if (count == 0) return false;
    renderer_.prepare(preset_.formula);
    const PlaneTile tile{width, height, 0, 0, width, height};
    renderer_.render(preset_.formula, preset_.colouring, rect_, tile, target_, refinement_.samplesDone, count,
                     refinement_.samplesDone > 0);
    refinement_.samplesDone += count;
    return true;
}

}  // namespace fraktal
