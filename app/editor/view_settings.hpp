// What the viewport draws besides the formula: march budget, progressive AA, shading and the
// display transform. Plain data, part of the undoable document.
//
// TODO(core/render): when core/render/settings.hpp lands, its shading settings replace the
// shading fields here so the viewport and the still export read the same struct.
#pragma once

#include <nlohmann/json.hpp>

#include "core/vec.hpp"

namespace fraktal::editor {

struct ViewSettings {
    // March budget: sphere-tracing steps per pixel per frame. On llvmpipe every step shows in
    // the frame time (shared/PLATFORM.md), so the editor default is modest.
    int maxSteps = 160;
    // Fraction of the window's pixels the viewport renders while the view moves (upscaled).
    double renderScale = 0.5;
    // Reuse converged samples while nothing changes (progressive accumulation).
    bool reprojection = true;
    // Jittered samples per pixel before the viewport stops rendering (converged).
    int aaCap = 8;

    vec3 lightDirection{0.55, 0.75, 0.35};
    bool shadows = true;
    bool ambientOcclusion = true;
    double fog = 0.15;        // density of the exponential distance fog
    int palette = 0;          // index into kPaletteNames (orbit-trap colouring, seed 3.3)
    double exposure = 0.0;    // stops, applied at display only (tev style: data stays linear)

    bool operator==(const ViewSettings&) const = default;
};

inline constexpr const char* kPaletteNames[] = {"Ember", "Ocean", "Bone", "Orbit trap RGB"};
inline constexpr int kPaletteCount = 4;

nlohmann::json viewSettingsToJson(const ViewSettings& s);
// Tolerant reader for the editor's own state: unknown or missing fields keep defaults.
ViewSettings viewSettingsFromJson(const nlohmann::json& j);

}  // namespace fraktal::editor
