// Remembers which panels are open in ImGui's ini file (ImGui itself stores their sizes), as a
// "[Fraktal][Panels]" section.
#pragma once

#include "app/editor/editor_state.hpp"

namespace fraktal::editor {

// Call after creating the ImGui context and before the first frame. `panels` must outlive it.
void registerPanelIniHandler(PanelVisibility& panels);

}  // namespace fraktal::editor
