// The editor's commands (what menus, shortcuts and drops trigger), independent of ImGui so the
// same code runs from a test. Each reports failures in state.status; none throws.
#pragma once

#include <filesystem>

#include "app/editor/editor_state.hpp"

namespace fraktal::editor {

// A fresh document: the shipped Mandelbulb if present, else a one-block default.
void newDocument(EditorState& s);
// Loads a preset (.json) or the preset embedded in an exported EXR. False on error (shown).
bool openDocument(EditorState& s, const std::filesystem::path& file);
// Adopts an autosaved document after a crash: it keeps its original file (if any) and counts
// as unsaved until the user saves it.
void restoreDocument(EditorState& s, RecoveryOffer offer);
bool saveDocument(EditorState& s);  // to s.file.path; false when there is none (use Save As)
bool saveDocumentAs(EditorState& s, const std::filesystem::path& file);
void undo(EditorState& s);
void redo(EditorState& s);
// Runs `action` now, or asks first when there are unsaved changes.
void requestAction(EditorState& s, PendingAction action);
void runPending(EditorState& s);

void setStatus(EditorState& s, std::string text, bool error = false);

// Reads the preset that `fraktal render` embeds in an EXR header (any string attribute that
// parses as a fraktal preset). Throws PresetError naming the file when there is none.
Preset presetFromExr(const std::filesystem::path& file);

}  // namespace fraktal::editor
