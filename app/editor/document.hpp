// The document the editor edits: the preset (formula, camera, render and shading settings), the
// viewport's view settings and the saved view slots. Everything in here is undoable and is what
// "unsaved changes" compares.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "app/editor/view_settings.hpp"
#include "core/preset.hpp"

namespace fraktal::editor {

inline constexpr int kViewSlots = 4;

struct Document {
    Preset preset;
    ViewSettings view;
    std::array<std::optional<Camera>, kViewSlots> viewSlots;
};

// A canonical text form of the whole document. Two documents with the same fingerprint are
// the same state (doubles are written with round-trip precision), which is what undo and the
// unsaved-changes mark compare.
std::string fingerprint(const Document& d);

// The preset's own "editor" section keeps view settings and slots with the file, so a saved
// scene reopens as it was left. The preset format keeps unknown sections (Preset::extra).
void storeEditorSection(Document& d);
void loadEditorSection(Document& d);

}  // namespace fraktal::editor
