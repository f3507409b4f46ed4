// The GL side of ui_redraw.hpp: a copy of the window's framebuffer, and the frame's draw data
// with the static windows (the side column and the menu bar) left out.
#pragma once

#include <epoxy/gl.h>
#include <imgui.h>

#include <vector>

#include "core/gl/color_target.hpp"

namespace fraktal::editor {

class UiLayerCache {
   public:
    // A rectangle of the framebuffer in pixels, from its top-left corner.
    struct Rect {
        int x = 0, y = 0, width = 0, height = 0;
    };
    // Copies the default framebuffer (width x height) into the cache, all but `hole` (the
    // viewport, which every frame draws whole): a copy costs per pixel on a software rasteriser
    // (measured on llvmpipe: 3.5 ms for a 1280x720 window).
    void capture(int width, int height, const Rect& hole);
    // Copies the cache back into the default framebuffer, all but `hole`.
    void restore(int width, int height, const Rect& hole) const;
    // `all` without the draw lists of the static windows, in the same order (valid until the next
    // call; non-const for ImGui's renderer).
    ImDrawData* liveLayers(const ImDrawData& all);

   private:
    void copyAround(GLuint from, GLuint to, int width, int height, const Rect& hole) const;
    gl::ColorTarget copy_{GL_RGBA8};
    std::vector<ImDrawList*> live_;
    ImDrawData liveData_;
};

// Whether a draw list belongs to a window that a camera gesture leaves unchanged: the side
// column's panels (and their child windows) and the main menu bar.
bool isStaticUiWindow(const char* ownerName);

}  // namespace fraktal::editor
