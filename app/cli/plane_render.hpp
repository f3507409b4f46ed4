// `fraktal render` of a 2D preset (presets/2d): app/cli/render.cpp hands 2D presets here with
// the options that apply to them.
#pragma once

#include <optional>
#include <string>

namespace fraktal::cli {

struct PlaneRenderRequest {
    std::string input, output, png;
    int width = 0, height = 0;  // 0: the preset's
    int spp = 0;                // 0: the preset's
    std::optional<double> exposure;
    std::string view, display, workingSpace;
    bool fullFloat = false;
    int threads = 0;
    int tile = 512;
    bool quiet = false;
    bool forceFloat = false;  // single precision even where fp64 exists (comparisons)
};

int runPlaneRender(const PlaneRenderRequest& request);

}  // namespace fraktal::cli
