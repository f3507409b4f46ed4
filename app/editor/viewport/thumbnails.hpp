// Renders the preset browser's thumbnails with a viewport of their own (the same renderer and
// display transform as the main one), one per frame, so opening the browser never stalls the UI
// for long.
#pragma once

#include <memory>

#include "app/editor/state/editor_state.hpp"
#include "app/editor/viewport/plane_viewport.hpp"
#include "app/editor/viewport/viewport_view.hpp"

namespace fraktal::editor {

struct ThumbnailRenderer {
    std::unique_ptr<ViewportView> viewport;  // created on first use
    std::unique_ptr<PlaneViewport> plane;    // for 2D presets (presets/2d), created on first use
    int width = 272, height = 170;
};

// Renders the next missing thumbnail of `b`, if any, to one anti-aliasing sample (2D: four). Returns
// whether it did work.
bool renderNextThumbnail(ThumbnailRenderer& r, PresetBrowser& b, const ColorPipeline& color);
void releaseThumbnails(PresetBrowser& b);

}  // namespace fraktal::editor
