// Where the last ImGui item was drawn, kept by name for the state file (Layout::widgetRects), so
// that tests driving the real editor click widgets where they are, not at fixed points.
#pragma once

#include <imgui.h>

#include <array>
#include <map>
#include <string>

namespace fraktal::editor {

// The last item's rectangle as x, y, w, h in window coordinates, under `name`.
inline void noteItemRect(std::map<std::string, std::array<float, 4>>& rects, const std::string& name) {
    const ImVec2 lo = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
    rects[name] = {lo.x, lo.y, size.x, size.y};
}

}  // namespace fraktal::editor
