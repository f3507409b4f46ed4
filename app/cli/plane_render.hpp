// `fraktal render` of a 2D preset (presets/2d): app/cli/render.cpp hands 2D presets here with
// the options that apply to them.
#pragma once

#include <optional>
#include <string>

#include "core/plane/plane_preset.hpp"

namespace fraktal::cli {

struct PlaneRenderRequest {
    std::string input, output, png;  // input: for messages
    int width = 0, height = 0;       // 0: the preset's
    int spp = 0;                     // 0: the preset's
    std::optional<double> exposure;
    std::string view, display, workingSpace;
    bool fullFloat = false;
    int threads = 0;
    int tile = 512;
    bool quiet = false;
    bool forceFloat = false;  // single precision even where fp64 exists (comparisons)
};

// Renders `preset` (loaded by the caller from a 2D preset file or a 2D still's EXR) with the
// request's overrides.
int runPlaneRender(const PlaneRenderRequest& request, PlanePreset preset);

}  // namespace fraktal::cli
