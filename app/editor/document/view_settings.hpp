// How the editor's viewport works through a view, apart from what the preset says about the
// image: the march budget per frame, the render resolution, reprojection, colour carry, the
// motion filter and the AA cap.
// Everything about the image itself (march steps per ray, detail, shading, exposure, OCIO view)
// is the preset's `render` and `shading` sections (core/render_settings.hpp), which the viewport
// and the still export both read. Plain data, part of the undoable document, saved in the
// preset's "editor" section.
#pragma once

#include <nlohmann/json.hpp>

#include "core/viewport/resolution_control.hpp"
#include "core/viewport/viewport_options.hpp"

namespace fraktal::editor {

struct ViewSettings {
    // March steps per ray per frame (viewport::ViewportOptions::stepsPerFrame). On llvmpipe
    // every step shows in the frame time (shared/PLATFORM.md): a modest budget keeps the UI
    // responsive, and unfinished rays continue next frame. At rest a frame refines the slice of
    // the view that fits viewport::kRestFrameTargetMs (viewport::RestSlices), each of its rays by
    // these steps.
    int stepsPerFrame = 30;
    // Fraction of the window's pixels the viewport renders (upscaled for display).
    double renderScale = 0.75;
    // Dynamic resolution: while the camera or a parameter moves, the viewport renders at the share
    // of renderScale's size that holds this frame time (viewport::ResolutionController), and
    // refines at full size once the view rests. 0: always full size.
    double frameTimeTargetMs = 33.0;
    // The smallest share of each side it may go down to (viewport::ResolutionControl::minScale).
    double motionMinScale = viewport::ResolutionControl{}.minScale;
    // Carry march distances over when the camera moves (seed 4.2); off: every move restarts.
    bool reprojection = true;
    // Progressive anti-aliasing cap: jittered samples per pixel while the camera rests.
    int aaCap = 8;
    // Cone pre-pass tile in pixels (0: off).
    int coneTile = 0;
    // Under motion a reprojected hit keeps its carried colour for at most this many frames
    // (viewport::ViewportOptions::maxCarryFrames; 0: shade every hit).
    int maxCarryFrames = viewport::ViewportOptions{}.maxCarryFrames;
    // Under motion show a reconstruction from the scattered samples (ViewportOptions::motionFilter).
    bool motionFilter = true;
    double motionFilterRadius = viewport::ViewportOptions{}.motionFilterRadius;  // pixels
    // Under motion stop rays that keep a carried colour near the surface (ViewportOptions::coarseHits).
    bool coarseHits = true;
    // Render mode: false renders the fast mode always; true renders it while the view moves and,
    // once the view rests, path-traces it (core/render/path_tracer.hpp, the scene of `fraktal
    // render --mode path`) at the viewport's full size, accumulating up to pathSppCap samples per
    // pixel.
    bool pathTraceAtRest = false;
    int pathSppCap = 256;

    bool operator==(const ViewSettings&) const = default;
};

nlohmann::json viewSettingsToJson(const ViewSettings& s);
// Tolerant reader for the editor's own state: unknown or missing fields keep defaults.
ViewSettings viewSettingsFromJson(const nlohmann::json& j);

}  // namespace fraktal::editor
