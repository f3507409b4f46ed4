// Renders the preset browser's thumbnails with a viewport of their own (the same renderer and
// display transform as the main one), a little each frame, so that showing the browser never
// holds the window: a thumbnail's programs compile on a worker thread of their own, and each
// frame renders its next march steps for a few milliseconds. A 3D thumbnail used to compile and
// render whole in one frame: with the Presets tab open, frames took 200-2570 ms each for 40
// frames on llvmpipe (two cores).
#pragma once

#include <filesystem>
#include <memory>

#include "app/editor/document/document.hpp"
#include "app/editor/state/editor_state.hpp"
#include "app/editor/viewport/background_compiler.hpp"
#include "app/editor/viewport/plane_viewport.hpp"
#include "app/editor/viewport/viewport_view.hpp"

namespace fraktal::editor {

struct ThumbnailRenderer {
    // The thumbnails' own compiler (the main viewport's keeps only the newest structure asked of
    // it); null: they compile in the frame. Declared before the viewport that uses it.
    std::unique_ptr<BackgroundCompiler> compiler;
    std::unique_ptr<ViewportView> viewport;  // created on first use
    std::unique_ptr<PlaneViewport> plane;    // for 2D presets (presets/2d), created on first use
    int width = 272, height = 170;
    double budgetMs = 12.0;  // main-thread time a frame gives the thumbnails

    // The thumbnail in progress across frames: its file (empty: none), its document, frames so far.
    std::filesystem::path file;
    Document document;
    int frames = 0;
};

// Renders for about r.budgetMs towards the missing thumbnails of `b`, in order: each 3D one to
// one anti-aliasing sample, each 2D one to four. Returns whether any is still missing.
bool renderNextThumbnail(ThumbnailRenderer& r, PresetBrowser& b, const ColorPipeline& color);
void releaseThumbnails(PresetBrowser& b);

}  // namespace fraktal::editor
