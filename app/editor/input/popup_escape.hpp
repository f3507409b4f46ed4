// Escape closes the menu or popup in front, as in Dear ImGui with keyboard navigation on. The
// editor leaves ImGui's keyboard navigation off (arrows, Space and Enter would move a focus
// highlight instead of reaching the viewport and the timeline), and ImGui 1.86 then ignores
// Escape: the menu stayed open, and the next click, landing outside it, only closed it.
#pragma once

#include <vector>

namespace fraktal::editor {

// How many of the open popups stay open after an Escape press. `modal` lists ImGui's popup stack
// from the bottom (the first opened) to the top; `itemActive`: a widget is being edited (a text
// field, a drag), which Escape ends first. A modal dialog on top handles Escape itself (its
// Cancel), so it is left open; a submenu closes before the menu it opened from.
inline int popupsLeftOpenByEscape(const std::vector<bool>& modal, bool itemActive) {
    const int open = int(modal.size());
    if (itemActive || open == 0 || modal.back()) return open;
    return open - 1;
}

}  // namespace fraktal::editor
