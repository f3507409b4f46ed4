// Drawing less of the UI while the camera moves. On a software rasteriser (llvmpipe) Dear ImGui's
// panels cost more per frame than the viewport itself (bench/viewport/README.md, "The editor
// under a person's hands"), yet during an orbit or fly gesture the side column and the menu bar
// barely change. So during a camera gesture the editor draws the whole window once, keeps a copy
// of it, and on the following frames copies that back and draws only the live layers over it: the
// viewport image, its overlays, the timeline, popups and dialogs. Every kUiRefreshFrames-th frame
// of the gesture is drawn whole, so the column's numbers (the Camera tab's position) keep up, and
// the first frame after the gesture is drawn whole again.
#pragma once

namespace fraktal::editor {

inline constexpr int kUiRefreshFrames = 8;

enum class UiDraw {
    Full,            // draw every window
    FullAndCapture,  // draw every window, then keep a copy of the window
    Cached,          // the kept copy, then only the live windows over it
};

struct UiRedrawState {
    bool captured = false;  // a copy of this size is kept
    int width = 0, height = 0;
    int framesSinceCapture = 0;
};

// The plan of this frame. `gesture`: a camera drag or fly key is held. `enabled` false (a test
// or a user who wants every frame whole) always draws in full.
UiDraw planUiDraw(UiRedrawState& state, bool gesture, int width, int height, bool enabled = true);

// "full", "capture" or "cached", as the frame log and the state file say it.
const char* uiDrawName(UiDraw draw);

}  // namespace fraktal::editor
