// A 2D still: the view rendered tile by tile with supersampling into a scene-linear EXR with
// AOVs (R G B A, inside = fraction of samples in the set, iterations = mean smooth iteration count
// and distance = mean distance estimate of the outside samples) and an optional PNG through the
// same OCIO display/view path as 3D stills. Files are written atomically (core/image).
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "core/color/color_pipeline.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_renderer.hpp"

namespace fraktal {

// EXR header attribute holding the 2D preset (3D stills use "fraktal.preset").
inline constexpr const char* kExrPlanePresetAttribute = "fraktal.planePreset";

struct PlaneStillJob {
    PlanePreset preset;  // preset.render: size, spp and colour settings actually used
    std::filesystem::path exr;
    std::optional<std::filesystem::path> png;
    bool fullFloat = false;
    int tileSize = 512;
    PlanePrecision precision = PlanePrecision::Auto;
    std::function<void(int tilesDone, int tilesTotal)> onProgress;
    const std::atomic<bool>* cancel = nullptr;  // polled between tiles: throws RenderCancelled
};

// Linear Rec.709 (the 2D renderer's colours) -> the working space, as a matrix whose columns
// are the images of the unit primaries: exact for the linear working spaces configs offer.
mat3 planeWorkingFromRec709(const ColorPipeline& color, const std::string& workingSpace);

// The 2D preset embedded in a 2D still's EXR header (kExrPlanePresetAttribute), or nullopt when
// the file is an EXR without one. Throws std::runtime_error naming the file when it cannot be
// read as an EXR.
std::optional<std::string> readExrPlanePreset(const std::filesystem::path& path);

// Checks sizes, outputs and colour settings before rendering (the 3D still's checks); throws
// std::runtime_error saying what is wrong.
void validatePlaneStillJob(const PlaneStillJob& job, const ColorPipeline& color);

// Renders and writes the files; needs a current GL context. Returns the renderer's warnings
// (no fp64, float powers) for the caller to print.
std::vector<std::string> renderPlaneStill(const PlaneStillJob& job, const ColorPipeline& color);

}  // namespace fraktal
