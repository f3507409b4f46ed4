// The editor's entry point: a GLFW window with Dear ImGui panels around the viewport.
#pragma once

#include <filesystem>
#include <string>

namespace fraktal::editor {

struct EditorOptions {
    std::filesystem::path preset;           // opened at start (empty: a new document)
    int frames = 0;                         // > 0: draw this many frames, then exit
    std::filesystem::path screenshot;       // with frames: a PNG of the whole window after the last
    bool untilSettled = false;              // with frames: end at the first frame the view has settled
    int width = 0, height = 0;              // 0: the size remembered from the last run, else 1280x800
    bool useIniFile = true;                 // false for reproducible screenshots
    std::string sidebarTab;                 // Scene tab shown first: Camera, Render, Shading or Presets
    bool sessionRecovery = true;            // autosave and the restore prompt (off for scripted runs)
    std::filesystem::path stateFile;        // set: the editor state as JSON after every frame (tests)
    int slowFrameMs = 0;                    // > 0: every frame sleeps this long (tests of input timing)
    std::filesystem::path frameLog;         // non-empty: one JSON line per frame (frame_log.hpp)
    int exportWidth = 0, exportHeight = 0;  // > 0: the export dialog's size at start (Custom)
    std::filesystem::path dropReplay;       // tests: files listed here are dropped on the window
    bool uiCache = true;                    // false: every frame draws every window (viewport/ui_redraw.hpp)
    int aaCapLimit = 0;                     // > 0: the viewport's AA cap at most this (the document keeps its own)
};

// Returns the process exit status. With no display it prints why and points to
// `fraktal render` (exit 3); a bad preset is reported in the window's status line.
int runEditor(const EditorOptions& options);

// Whether a display server is reachable ($DISPLAY or $WAYLAND_DISPLAY set).
bool displayAvailable();

}  // namespace fraktal::editor
