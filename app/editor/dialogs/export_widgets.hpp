// What the still and the mesh export dialogs draw alike for their child process
// (document/export_process.hpp): the progress bar or the status line, and the command and log.
#pragma once

#include <string>

#include "app/editor/panels/panels.hpp"

namespace fraktal::editor {

// The text width of an export dialog.
float exportDialogWidth();
// Opens an export dialog's window `title` (closed by its x into `open`), centred when it appears:
// it sizes itself to what it shows (the log opened, a longer status), its text wrapped at
// exportDialogWidth(), so that nothing in it is cut or scrolls out of sight. False when it is not
// drawn (nothing to end); else endExportDialog() closes it.
bool beginExportDialog(const char* title, bool* open);
void endExportDialog();
// The job's state beside its Render / Export button: a progress bar while it runs (with `stage`
// in it when the child names one; `verb` and the elapsed time when it gives no percentage:
// "meshing, 12 s"), else `status` (green for a Done whose files exist, red for a failure).
void drawExportProgress(const ExportProcess& job, const std::string& status, const std::string& stage, const char* verb,
                        double now);
// The collapsible "Command and log": the command as it runs, the child's output wrapped at the
// dialog's width in a region as tall as the log up to half the window, scrolled to its newest
// line. The header's rect is noted under `rectName`.
void drawExportLog(EditorState& s, const ExportProcess& job, const std::string& command, const std::string& rectName);

}  // namespace fraktal::editor
