// Runs a viewport on a still camera until it settles (every pixel at the AA cap): the "fresh full
// render" that tests and the benchmark compare progressive and reprojected frames against.
#pragma once

#include <vector>

#include "core/viewport/viewport.hpp"

namespace fraktal::viewport {

struct Converged {
    std::vector<float> image;  // RGBA scene-linear, rows from the top
    int frames = 0;            // frames until settled
    bool settled = false;      // false: maxFrames ran out first
};

// Renders frames of an unchanged view until the viewport settles or maxFrames pass.
Converged renderUntilSettled(Viewport& viewport, const Formula& formula, const Camera& camera,
                             const RenderSettings& render, const ShadingSettings& shading, int width, int height,
                             int maxFrames, const ThinLens& lens = {});

}  // namespace fraktal::viewport
