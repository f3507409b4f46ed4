// Remembers which panels are open, the side column's width and split, and the window's size and
// place in ImGui's ini file (in the editor's config folder), as a "[Fraktal][Panels]" section.
#pragma once

#include "app/editor/state/editor_state.hpp"

namespace fraktal::editor {

// Call after creating the ImGui context and before the ini file is read. `s` must outlive it.
void registerPanelIniHandler(EditorState& s);

}  // namespace fraktal::editor
