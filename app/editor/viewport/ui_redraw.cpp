#include "app/editor/viewport/ui_redraw.hpp"

namespace fraktal::editor {

UiDraw planUiDraw(UiRedrawState& state, bool gesture, int width, int height, bool enabled) {
    if (!enabled || !gesture) {
        state.captured = false;
        return UiDraw::Full;
    }
    const bool stale = !state.captured || state.width != width || state.height != height ||
                       state.framesSinceCapture + 1 >= kUiRefreshFrames;
    if (stale) {
        state = {true, width, height, 0};
        return UiDraw::FullAndCapture;
    }
    ++state.framesSinceCapture;
    return UiDraw::Cached;
}

const char* uiDrawName(UiDraw draw) {
    switch (draw) {
        case UiDraw::Full: return "full";
        case UiDraw::FullAndCapture: return "capture";
        case UiDraw::Cached: return "cached";
    }
    return "full";
}

}  // namespace fraktal::editor
