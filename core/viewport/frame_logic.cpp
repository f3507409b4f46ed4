#include "core/viewport/frame_logic.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/preset.hpp"

namespace fraktal::viewport {

const char* toString(FrameAction a) {
    switch (a) {
        case FrameAction::Reset: return "reset";
        case FrameAction::Hold: return "hold";
        case FrameAction::Reproject: return "reproject";
        case FrameAction::Continue: return "continue";
    }
    return "?";
}

std::string formulaValuesKey(const Formula& f) { return formulaToJson(f).dump(); }

FrameAction decideFrame(const FrameKey* previous, const FrameKey& current, bool reprojectEnabled,
                        FrameAction previousAction) {
    if (!previous) return FrameAction::Reset;
    const bool resized = previous->width != current.width || previous->height != current.height;
    if (previous->structure != current.structure || previous->values != current.values) return FrameAction::Reset;
    if (!(previous->shading == current.shading) || previous->maxSteps != current.maxSteps ||
        !(previous->lens == current.lens))
        return FrameAction::Reset;
    if (previous->camera == current.camera) {
        const bool moving = previousAction == FrameAction::Reproject || previousAction == FrameAction::Hold;
        if (resized) return moving && reprojectEnabled ? FrameAction::Reproject : FrameAction::Reset;
        if (previousAction == FrameAction::Reproject) return FrameAction::Hold;
        return previousAction == FrameAction::Hold ? FrameAction::Reset : FrameAction::Continue;
    }
    return reprojectEnabled ? FrameAction::Reproject : FrameAction::Reset;
}

glm::dvec2 aaJitter(int sampleIndex) {
    if (sampleIndex <= 0) return glm::dvec2(0.0);
    // R2: the plastic number g solves g^3 = g + 1; alpha = (1/g, 1/g^2).
    const double g = 1.32471795724474602596;
    const glm::dvec2 alpha(1.0 / g, 1.0 / (g * g));
    const glm::dvec2 u = glm::fract(0.5 + alpha * double(sampleIndex));
    return u - 0.5;
}

int AASchedule::next(int finishedSample, bool cameraAtRest) const {
    if (!cameraAtRest) return -1;
    const int following = finishedSample + 1;
    return following < maxSamples ? following : -1;
}

double extendConeCoverage(double covered, double t, double d, double tanHalfAngle) {
    if (tanHalfAngle >= 1.0 || d <= 0.0) return covered;
    const double nearEnd = (t - d) / (1.0 - tanHalfAngle);
    const double farEnd = (t + d) / (1.0 + tanHalfAngle);
    if (nearEnd > covered || farEnd <= covered) return covered;
    return farEnd;
}

double reprojectionMargin(double t, double pixelAngle, double detail) {
    return 2.0 * pixelAngle * t * std::max(detail, 1.0);
}

double parkedDistance(double cameraDistance, double boundRadius) { return cameraDistance + 2.0 * boundRadius; }

double hash01(uint32_t x, uint32_t y, uint32_t z) {
    x = x * 1664525u + 1013904223u;
    y = y * 1664525u + 1013904223u;
    z = z * 1664525u + 1013904223u;
    x += y * z;
    y += z * x;
    z += x * y;
    x ^= x >> 16u;
    y ^= y >> 16u;
    z ^= z >> 16u;
    x += y * z;
    return double(x >> 8u) / 16777216.0;
}

bool carriedColourExpires(int carryAge, int maxCarryFrames, int px, int py) {
    if (carryAge <= maxCarryFrames - maxCarryFrames / 4) return false;
    if (carryAge > maxCarryFrames) return true;
    return hash01(uint32_t(px), uint32_t(py), uint32_t(carryAge)) * double(maxCarryFrames - carryAge + 2) < 1.0;
}

int sliceOfFrame(int frame, int slices) {
    if (slices <= 1) return 0;
    const int position = ((frame % slices) + slices) % slices;
    if ((slices & (slices - 1)) != 0) return position;
    int reversed = 0;
    for (int bit = 1, mirror = slices >> 1; bit < slices; bit <<= 1, mirror >>= 1)
        if (position & bit) reversed |= mirror;
    return reversed;
}

void SliceProgress::record(bool newView, int slices, int slice, uint64_t busyPixels, uint64_t convergedPixels) {
    slices = std::max(slices, 1);
    if (newView || busy.size() != size_t(slices)) {
        busy.assign(size_t(slices), -1);
        converged.assign(size_t(slices), 0);
    }
    const size_t at = size_t(std::clamp(slice, 0, slices - 1));
    busy[at] = int64_t(busyPixels);
    converged[at] = convergedPixels;
}

bool SliceProgress::settled() const {
    return !busy.empty() && std::all_of(busy.begin(), busy.end(), [](int64_t b) { return b == 0; });
}

uint64_t SliceProgress::convergedPixels() const {
    uint64_t sum = 0;
    for (uint64_t c : converged) sum += c;
    return sum;
}

FrameStats summarize(const FrameCounters& c, int width, int height, FrameAction action) {
    FrameStats s;
    s.action = action;
    s.width = width;
    s.height = height;
    const double pixels = std::max(1.0, double(width) * double(height));
    s.deEvalsPerPixel = double(c.deEvals) / pixels;
    s.shadeDeEvalsPerPixel = double(c.shadeDeEvals) / pixels;
    s.shareReprojected = double(c.reprojected) / pixels;
    s.shareRestarted = double(c.restarted) / pixels;
    s.shareConverged = double(c.converged) / pixels;
    s.shareShaded = double(c.shaded) / pixels;
    s.shareMarchListed = double(c.marchListed) / pixels;
    return s;
}

}  // namespace fraktal::viewport
