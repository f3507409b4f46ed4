// Flies a scripted camera path through a viewport and records per-frame statistics and the error
// of each frame against a converged render of the same view: the engine of `fraktal bench
// viewport` and of the viewport's work tests.
#pragma once

#include <filesystem>
#include <vector>

#include "core/preset.hpp"
#include "core/viewport/camera_path.hpp"
#include "core/viewport/viewport.hpp"

namespace fraktal::viewport {

struct FlightSettings {
    CameraPath path = CameraPath::Orbit;
    int frames = 30;  // moving frames
    // Start from the view at rest (settled at the AA cap, not counted), as a user's orbit does,
    // rather than from an empty viewport whose first frame restarts every ray in every mode.
    bool fromRest = false;
    double degreesPerFrame = 0.5;
    int width = 640, height = 360;
    // The grid of the moving frames when not 0 (the editor's dynamic resolution moves on a grid a
    // fraction of the one at rest: the first moving frame scatters the whole rest grid into it).
    int motionWidth = 0, motionHeight = 0;
    ViewportOptions options;
    // Per-frame PSNR against the fully converged render of the view (a fresh viewport settled at
    // options.maxSamples: the anti-aliased image the camera stopping there would give), and
    // against a converged single-sample (pixel-centre) render. Under motion every scheme draws one
    // sample per pixel, and a sample from elsewhere in the pixel (a reprojected colour) differs
    // from the centre sample by the pixel's aliasing, which the anti-aliased reference does not
    // count as error; the centre reference does, and favours restarting from the camera.
    bool measureError = true;
    int maxRestFrames = 400;    // after the path: frames at rest until settled
    bool restAfterPath = true;  // false: stop after the moving frames (timing runs at large sizes)
    double restThresholdDb = 40.0;
    // When set: each moving frame and its reference as DIR/frame_NNN.png and frame_NNN_ref.png
    // (sRGB display of the scene-linear images), for looking at what an error figure means.
    std::filesystem::path dumpDirectory;
};

struct FlightFrame {
    FrameStats stats;
    double psnrDb = 0.0;        // vs the fully converged (anti-aliased) render of this view (NaN: not measured)
    double psnrCentreDb = 0.0;  // vs the converged single-sample (pixel-centre) render of this view
};

struct FlightResult {
    std::vector<FlightFrame> frames;  // the moving frames
    double meanDeEvalsPerPixel = 0.0, meanShadeDeEvalsPerPixel = 0.0, meanMilliseconds = 0.0;
    double meanPsnrDb = 0.0, meanPsnrCentreDb = 0.0;
    // After the camera stops: frames until the image is within restThresholdDb of the settled
    // image, frames until settled (and their wall time), and the DE cost of a frame once settled.
    int restFramesToThreshold = -1, restFramesToSettle = -1;
    double restMillisecondsToSettle = 0.0;
    double settledDeEvalsPerPixel = 0.0;
};

FlightResult fly(const Preset& preset, const FlightSettings& settings);

}  // namespace fraktal::viewport
