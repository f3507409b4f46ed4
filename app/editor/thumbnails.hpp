// Renders the preset browser's thumbnails with a viewport of their own, one per frame, so
// opening the browser never stalls the UI for long.
#pragma once

#include <memory>

#include "app/editor/editor_state.hpp"
#include "app/editor/viewport_view.hpp"

namespace fraktal::editor {

struct ThumbnailRenderer {
    std::unique_ptr<ViewportView> viewport;  // created on first use
    int width = 272, height = 170;
};

// Renders the next missing thumbnail of `b`, if any. Returns whether it did work.
bool renderNextThumbnail(ThumbnailRenderer& r, PresetBrowser& b);
void releaseThumbnails(PresetBrowser& b);

}  // namespace fraktal::editor
