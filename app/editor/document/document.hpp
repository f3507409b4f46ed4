// The document the editor edits: the preset (formula, camera, render and shading settings), the
// viewport's view settings and the saved view slots; or, for a 2D preset (presets/2d), the
// plane preset (2D formula, view rectangle, colouring). Everything in here is undoable and is
// what "unsaved changes" compares.
#pragma once

#include <array>
#include <filesystem>
#include <optional>
#include <string>

#include "app/editor/document/view_settings.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/preset.hpp"

namespace fraktal::editor {

inline constexpr int kViewSlots = 4;

struct Document {
    Preset preset;  // the 3D scene (unused while `plane` holds a value)
    ViewSettings view;
    std::array<std::optional<Camera>, kViewSlots> viewSlots;
    // Set: a 2D document, shown by the 2D view (core/plane/plane_view.hpp) and saved as a 2D
    // preset; its view rectangle is where the user panned and zoomed to.
    std::optional<PlanePreset> plane;

    bool isPlane() const { return plane.has_value(); }
};

// A canonical text form of the whole document. Two documents with the same fingerprint are
// the same state (doubles are written with round-trip precision), which is what undo and the
// unsaved-changes mark compare.
std::string fingerprint(const Document& d);

// The document's file text: a 3D preset with its "editor" section, or a 2D preset.
std::string documentFileText(const Document& d);

// The preset's own "editor" section keeps view settings and slots with the file, so a saved
// scene reopens as it was left. The preset format keeps unknown sections (Preset::extra).
void storeEditorSection(Document& d);
void loadEditorSection(Document& d);

}  // namespace fraktal::editor
