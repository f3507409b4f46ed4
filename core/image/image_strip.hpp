// A band of full-width image rows as the still renderer produces them, scene-linear floats. The
// renderer fills strips one after the other; the writers consume them (bounded memory: the whole
// image never exists at once).
#pragma once

#include <array>
#include <vector>

namespace fraktal {

struct ImageStrip {
    int width = 0;
    int y0 = 0;  // first row, counted from the top of the image
    int rows = 0;
    // Four floats per pixel each, row-major from (0, y0):
    std::vector<float> rgba;         // colour, alpha = coverage
    std::vector<float> normalDepth;  // world normal (coverage-weighted), depth of the nearest hit (1e30: none)
    std::vector<float> albedoAO;     // surface albedo (palette or object colour), ambient occlusion (coverage-weighted)
    std::vector<float> stats;        // DE evaluations / spp, march steps per camera ray, samples taken, 0

    // The four buffers in a fixed order (rgba, normalDepth, albedoAO, stats), for code that walks them.
    std::array<std::vector<float>*, 4> buffers() { return {&rgba, &normalDepth, &albedoAO, &stats}; }
    std::array<const std::vector<float>*, 4> buffers() const { return {&rgba, &normalDepth, &albedoAO, &stats}; }

    void resize(int w, int firstRow, int rowCount) {
        width = w;
        y0 = firstRow;
        rows = rowCount;
        const size_t n = size_t(w) * size_t(rowCount) * 4;
        rgba.assign(n, 0.0f);
        normalDepth.assign(n, 0.0f);
        albedoAO.assign(n, 0.0f);
        stats.assign(n, 0.0f);
    }
};

}  // namespace fraktal
