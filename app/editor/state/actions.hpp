// The editor's commands (what menus, shortcuts and drops trigger), independent of ImGui so the
// same code runs from a test. Each reports failures in state.status; none throws.
#pragma once

#include <filesystem>
#include <optional>

#include "app/editor/state/editor_state.hpp"

namespace fraktal::editor {

// A fresh document: the shipped Mandelbulb if present, else a one-block default.
void newDocument(EditorState& s);
// A fresh 2D document: the shipped Mandelbrot set if present, else z^2 + c with escape.
void newPlaneDocument(EditorState& s);
// Loads a preset (.json, 3D or 2D) or the preset embedded in an exported EXR (3D or 2D still).
// False on error (shown).
bool openDocument(EditorState& s, const std::filesystem::path& file);
// Applies the opened frag's #preset `name` as FragM does: the frag is imported again with it and
// its values (the DE's parameters, the camera, the raytracer's settings) replace the document's,
// one undo step; the step factor the editor measured for the DE is kept (a preset's FudgeFactor is
// no measurement). False, with the reason on the status line, where the frag no longer imports.
bool applyFragPreset(EditorState& s, const std::string& name);
// A file dropped on the window: opened (asking about unsaved changes first) when it is a preset
// or an EXR with a fraktal preset in its header; anything else is refused with a message naming
// the file and the reason, and changes nothing.
void openDropped(EditorState& s, const std::filesystem::path& file);
// The document in a preset file or an EXR that fraktal wrote; throws PresetError naming the file.
Document loadDocument(const std::filesystem::path& file);
// Back to the view the 2D document was opened with (2D "reset view").
void resetPlaneView(EditorState& s);
// Adopts an autosaved document after a crash: it keeps its original file (if any) and counts
// as unsaved until the user saves it.
void restoreDocument(EditorState& s, RecoveryOffer offer);
bool saveDocument(EditorState& s);  // to s.file.path; false when there is none (use Save As)
bool saveDocumentAs(EditorState& s, const std::filesystem::path& file);
// Undo and redo bring the state back with its step factor (AutoStepFactor::restore): nothing is
// measured again for a structure measured to the end.
void undo(EditorState& s);
void redo(EditorState& s);
// Each frame, for a 3D document: the step factor measured for the document's structure
// (AutoStepFactor::update) is applied to it and, once that structure is the undo history's
// present state (the edit that made it committed, or brought back by undo / redo), to that state
// in place: the factor is part of the edit's step, never a step of its own, and redo is kept.
// Returns whether a factor was measured or applied.
bool updateDerivedValues(EditorState& s, const std::string& structure);
inline bool updateDerivedValues(EditorState& s) {
    return updateDerivedValues(s, s.doc.plane ? std::string() : s.doc.preset.formula.structureKey());
}
// Runs `action` now, or asks first when there are unsaved changes.
void requestAction(EditorState& s, PendingAction action);
void runPending(EditorState& s);

void setStatus(EditorState& s, std::string text, bool error = false);

// Reads the preset that `fraktal render` embeds in an EXR header (any string attribute that
// parses as a fraktal preset). Throws PresetError naming the file when there is none.
Preset presetFromExr(const std::filesystem::path& file);
// The same for a 2D still (its `fraktal.planePreset` attribute); nullopt when it is none.
std::optional<PlanePreset> planePresetFromExr(const std::filesystem::path& file);

}  // namespace fraktal::editor
