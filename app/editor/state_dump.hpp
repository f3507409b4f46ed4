// The editor's state as JSON, written after every frame to a file that a test driving the real
// editor (tests/editor_user_stories.sh) reads: camera, modes, undo list, layout, status line,
// the selected node's parameter widgets and the tooltip shown over one, and the document itself.
#pragma once

#include <filesystem>
#include <string>

#include "app/editor/state/editor_state.hpp"
#include "app/editor/viewport/ui_redraw.hpp"
#include "app/editor/viewport/viewport_view.hpp"

namespace fraktal::editor {

// `viewportSettled`: the viewport's image is converged at full resolution, and nothing pending (a
// compile, the step factor's further rounds) will change it.
// `viewport`: the 3D viewport's statistics (null for a 2D document), for its render mode.
std::string stateJson(const EditorState& s, int frame, const std::string& compileError, bool viewportSettled,
                      const ViewportStats* viewport = nullptr, UiDraw ui = UiDraw::Full);

// Writes `text` to `file` atomically when it differs from `last` (then updates `last`); readers
// see a whole file, but nothing is flushed to disk (replaceFileForReaders).
void writeStateFile(const std::filesystem::path& file, const std::string& text, std::string& last);

// The frame's tick beside the state file, "<file>.frame": one line "FRAME PENDING SETTLED" (the
// frame count, the window events queued for later frames, and viewportSettled as true or false),
// which a test's shell reads with its own `read` on every poll while it waits on the editor
// (tests/editor_xvfb_helpers.sh): two jq processes per poll (33 ms of CPU each, ten polls a second)
// cost a waiting story about 40 % of a core.
std::string frameTickLine(int frame, int pendingInput, bool viewportSettled);
std::filesystem::path frameTickFile(const std::filesystem::path& stateFile);

}  // namespace fraktal::editor
