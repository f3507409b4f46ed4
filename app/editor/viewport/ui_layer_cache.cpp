#include "app/editor/viewport/ui_layer_cache.hpp"

#include <algorithm>
#include <cstring>

namespace fraktal::editor {

namespace {

bool startsWithWindow(const char* name, const char* window) {
    const size_t n = std::strlen(window);
    return std::strncmp(name, window, n) == 0 && (name[n] == '\0' || name[n] == '/');
}

}  // namespace

bool isStaticUiWindow(const char* ownerName) {
    if (!ownerName) return false;
    // The column's windows (panels/sidebar.cpp, beginSideColumnWindow) and ImGui's main menu bar.
    for (const char* window : {"Formula", "Scene", "##MainMenuBar"})
        if (startsWithWindow(ownerName, window)) return true;
    return false;
}

void UiLayerCache::copyAround(GLuint from, GLuint to, int width, int height, const Rect& hole) const {
    // The bands above, below, left and right of the hole, in GL's rows (from the bottom).
    const int x0 = std::clamp(hole.x, 0, width), x1 = std::clamp(hole.x + hole.width, x0, width);
    const int top = std::clamp(hole.y, 0, height), bottom = std::clamp(hole.y + hole.height, top, height);
    const int glLow = height - bottom, glHigh = height - top;   // the hole's rows in GL's order
    const Rect bands[] = {{0, glHigh, width, height - glHigh},  // above the hole
                          {0, 0, width, glLow},                 // below it
                          {0, glLow, x0, glHigh - glLow},       // left of it
                          {x1, glLow, width - x1, glHigh - glLow}};
    for (const Rect& b : bands) {
        if (b.width <= 0 || b.height <= 0) continue;
        glBlitNamedFramebuffer(from, to, b.x, b.y, b.x + b.width, b.y + b.height, b.x, b.y, b.x + b.width,
                               b.y + b.height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    }
}

void UiLayerCache::capture(int width, int height, const Rect& hole) {
    copy_.resize(width, height);
    copyAround(0, copy_.framebuffer(), width, height, hole);
}

void UiLayerCache::restore(int width, int height, const Rect& hole) const {
    copyAround(copy_.framebuffer(), 0, width, height, hole);
}

ImDrawData* UiLayerCache::liveLayers(const ImDrawData& all) {
    live_.clear();
    liveData_ = all;
    liveData_.TotalIdxCount = liveData_.TotalVtxCount = 0;
    for (int i = 0; i < all.CmdListsCount; ++i) {
        ImDrawList* list = all.CmdLists[i];
        if (isStaticUiWindow(list->_OwnerName)) continue;
        live_.push_back(list);
        liveData_.TotalIdxCount += list->IdxBuffer.Size;
        liveData_.TotalVtxCount += list->VtxBuffer.Size;
    }
    liveData_.CmdLists = live_.data();
    liveData_.CmdListsCount = int(live_.size());
    return &liveData_;
}

}  // namespace fraktal::editor
