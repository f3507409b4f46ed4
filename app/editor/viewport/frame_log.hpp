// `fraktal edit --frame-log FILE`: one JSON object per drawn frame (time, frame time and where it
// went, the viewport's work, its dynamic-resolution scale and render size, and the camera), for the
// viewport benchmark's editor run (bench/viewport/editor_run.sh) to read frame-time percentiles
// and the view the camera ended at.
#pragma once

#include <cstdio>
#include <filesystem>

#include "app/editor/viewport/ui_redraw.hpp"
#include "app/editor/viewport/viewport_view.hpp"
#include "core/camera.hpp"

namespace fraktal::editor {

struct FrameLog {
    std::FILE* file = nullptr;
    double lastFrameAt = -1.0;
};

// Where a frame's time went on the main thread (ms), for the log to say what held a long frame:
// waiting for and handling window events, building the panels (the viewport's render included,
// which the stats give apart), drawing the UI with GL, the buffer swap, and the hooks after it
// (the state file, the undo commit, the autosave).
struct FramePhases {
    double eventsMs = 0.0;
    double panelsMs = 0.0;
    double drawMs = 0.0;
    double swapMs = 0.0;
    double afterMs = 0.0;
};

// Opens (truncates) the log; throws std::runtime_error naming the file when it cannot.
void openFrameLog(FrameLog& log, const std::filesystem::path& path);
// Appends the frame that just ended at `now` (seconds) and flushes, so a killed editor leaves a
// complete log up to its last frame.
// `viewport`: the viewport's rectangle in the window (x, y, width, height); `thumbnails`: the
// Presets tab's thumbnails are still rendering (the next frame starts without waiting for input).
void logFrame(FrameLog& log, double now, const ViewportStats& stats, const Camera& camera, const float viewport[4],
              UiDraw ui = UiDraw::Full, bool thumbnails = false, const FramePhases& phases = {});
void closeFrameLog(FrameLog& log);

}  // namespace fraktal::editor
