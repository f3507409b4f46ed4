// Presets: the versioned JSON scene format (parsing here, separate from building GL state).
// Format: presets/README.md.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/render/settings.hpp"

namespace fraktal {

inline constexpr int kPresetVersion = 1;
inline constexpr std::string_view kPresetFormat = "fraktal-preset";

// A preset that cannot be used: says which file, which field (a JSON path such as
// formula.nodes[2].params.limit) and why.
class PresetError : public std::runtime_error {
public:
    PresetError(std::string file, std::string field, std::string reason);
    const std::string& file() const { return file_; }
    const std::string& field() const { return field_; }
    const std::string& reason() const { return reason_; }

private:
    std::string file_, field_, reason_;
};

struct Preset {
    std::string name;
    std::string description;
    Formula formula;
    Camera camera;
    RenderSettings render;    // "render" section (optional)
    ShadingSettings shading;  // "shading" section (optional)
    // Top-level sections this version does not know (from a newer fraktal), kept on save.
    nlohmann::json extra = nlohmann::json::object();
};

// `source` names the file in error messages.
Preset parsePreset(std::string_view text, const std::string& source);
Preset loadPreset(const std::filesystem::path& path);

// Writes only what differs from defaults, plus the format and version.
nlohmann::json presetToJson(const Preset& preset);
std::string serializePreset(const Preset& preset);
// Saves atomically (temp file, fsync, rename) and keeps the previous version as PATH.bak: if
// the program is killed mid-save, PATH is the complete old or the complete new preset.
void savePresetFile(const std::filesystem::path& path, const Preset& preset);

// A short human-readable listing of the formula (for `fraktal check`).
std::string describeFormula(const Formula& f);

}  // namespace fraktal
