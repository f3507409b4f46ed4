// 2D presets: the same versioned JSON format as 3D presets (core/preset.hpp) with a top-level
// "dimension": 2, a 2D formula ("start" and "nodes" of 2D blocks), a "view" (centre and width in
// the plane, in double) instead of a camera, and a "colouring" section instead of "shading".
// Format: presets/README.md, section "2D presets". Errors are PresetError (file, field, reason).
// The document guards, field reader, version migration and keeping of a newer version's fields
// are the 3D reader's (core/json_reader.hpp, core/preset.hpp).
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/plane/plane_colouring.hpp"
#include "core/plane/plane_formula.hpp"
#include "core/plane/plane_view_rect.hpp"
#include "core/preset.hpp"

namespace fraktal {

struct PlanePreset {
    std::string name;
    std::string description;
    PlaneFormula formula;
    PlaneViewRect view;
    RenderSettings render;  // width, height, spp and the colour settings (3D-only fields unused)
    PlaneColouring colouring;
    // As in Preset (core/preset.hpp): fields of a newer version kept for saving, the version
    // to save as, and what loading an older version changed.
    KeptFields unknownFields;
    int formatVersion = kPresetVersion;
    std::vector<std::string> migrationNotes;
};

// True when the JSON text is a preset with "dimension": 2 (false for 3D presets and for text
// that is not JSON at all: the 3D reader then reports what is wrong).
bool isPlanePresetText(std::string_view text);
bool isPlanePresetFile(const std::filesystem::path& path);

PlanePreset parsePlanePreset(std::string_view text, const std::string& file);
PlanePreset loadPlanePreset(const std::filesystem::path& path);

nlohmann::json planePresetToJson(const PlanePreset& preset);
// A short human-readable listing of the formula (for `fraktal check`), as describeFormula.
std::string describePlaneFormula(const PlaneFormula& f);
std::string serializePlanePreset(const PlanePreset& preset);

}  // namespace fraktal
