// Presets: the versioned JSON scene format (parsing here, separate from building GL state).
// Format: presets/README.md.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "core/animation.hpp"
#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/json_reader.hpp"
#include "core/lighting.hpp"
#include "core/preset_migrate.hpp"
#include "core/render_settings.hpp"

namespace fraktal {

// Version 2 moved the colour-management settings out of "render"; version 3 added the optional
// "animation" section (presets/README.md, "Versions"). Older files are migrated on load
// (core/preset_migrate.hpp), with a note.
inline constexpr int kPresetVersion = 3;
inline constexpr std::string_view kPresetFormat = "fraktal-preset";

struct Preset {
    std::string name;
    std::string description;
    Formula formula;
    Camera camera;
    RenderSettings render;    // "render" and "colorManagement" sections (optional)
    ShadingSettings shading;  // "shading" section (optional)
    Animation animation;      // "animation" section (optional; empty: a still)
    Lighting lighting;        // "lights", "environment", "pathTrace" and the camera's lens fields (optional)
    // Top-level sections this version does not know (from a newer fraktal, or the editor's own
    // "editor" section), kept on save.
    nlohmann::json extra = nlohmann::json::object();
    // Fields a newer format version added inside the known sections, written back on save.
    KeptFields unknownFields;
    // The version written on save: kPresetVersion, or a newer file's own version when it was
    // read from one (its unknown fields are kept, and a file that carries them must keep saying
    // it is of that version, or the next load would refuse them as typos).
    int formatVersion = kPresetVersion;
    // What loading changed to read a file of an older version, one note per step ("version 1 ->
    // 2: ..."); empty for a current file. Not saved: the next save writes the current version.
    std::vector<std::string> migrationNotes;
};

// A preset document after the checks that every preset, 3D or 2D, passes first: the JSON
// guards (json_reader.hpp), "format", a "version" that is known, migrated from an older
// version to kPresetVersion (the notes and moved fields in `migration`), or newer.
struct PresetDocument {
    nlohmann::json json;
    int fileVersion = kPresetVersion;  // as written in the file
    MigrationReport migration;
    bool newer() const { return fileVersion > kPresetVersion; }
};
PresetDocument readPresetDocument(std::string_view text, const std::string& file);
// `e`, raised while reading the migrated document, with its field named as in the file.
PresetError errorAsInFile(const PresetError& e, const PresetDocument& document);

// `source` names the file in error messages. `log`, when given, receives every field the
// readers asked about (json_reader.hpp, FieldLog).
Preset parsePreset(std::string_view text, const std::string& source, FieldLog* log = nullptr);
Preset loadPreset(const std::filesystem::path& path);

// The "colorManagement" section (working space, display, view, exposure; 3D and 2D alike), read
// into and written from the RenderSettings that carry it.
void parseColorManagement(const ReadContext& context, const nlohmann::json& j, RenderSettings& s);
nlohmann::json colorManagementJson(const RenderSettings& s);

// Pieces of the format that 3D and 2D presets (core/plane/plane_preset.cpp) share.
// When a node runs: "enabled" (default true), "period" and "phase" (default 1 and 0; the node
// runs on iterations i with i % period == phase), "start" and "stop" (default 0 and no end; the
// node runs on iterations start <= i < stop). NodeT: Node or PlaneNode.
template <class NodeT>
void readNodeSchedule(FieldReader& node, NodeT& n) {
    n.enabled = node.boolean("enabled", true);
    n.period = node.integer("period", 1, 1, kMaxPeriod);
    n.phase = node.integer("phase", 0, 0, kMaxPeriod - 1);
    if (n.phase >= n.period) node.fail("phase must be smaller than period (" + std::to_string(n.period) + ")", "phase");
    n.start = node.integer("start", 0, 0, kMaxIterations - 1);
    n.stop = node.integer("stop", kMaxIterations, 1, kMaxIterations);
    if (n.stop <= n.start) node.fail("stop must be greater than start (" + std::to_string(n.start) + ")", "stop");
}
// A node's "params": each of its block's declared parameters within its range (a toggle as
// true/false, a float as a number, a vector as an array; a direction not zero), any other key
// refused. Errors name the block as the editor's list shows it: "block N 'id': ..." (`listName`:
// "object N" for an object beside the fractal). `kind` says what the block is in the
// unknown-parameter message ("block", "2D block", "object"). NodeT: Node, PlaneNode or SceneObject.
template <class NodeT>
void readNodeParams(FieldReader& node, NodeT& n, size_t listNumber, const std::string& kind,
                    const std::string& listName = "block") {
    if (!node.has("params")) return;
    const std::string id(n.block->id);
    try {
        FieldReader params(node.context(), node.at("params"), node.child("params"));
        std::string known;
        for (size_t i = 0; i < n.block->params.size(); ++i) {
            const ParamDecl& d = n.block->params[i];
            const std::string key(d.name);
            known += (known.empty() ? "" : ", ") + key;
            if (d.type == ParamType::Toggle)
                n.values[i].x = params.toggle(key, d.defaultValue.x > 0.5) ? 1.0 : 0.0;
            else if (d.type == ParamType::Float)
                n.values[i].x = params.number(key, d.defaultValue.x, d.min, d.max);
            else
                n.values[i] = params.vector<3>(key, d.defaultValue, d.min, d.max);
            if (d.direction && length(n.values[i]) < 1e-9) params.fail("a direction must not be zero", key);
        }
        params.finish("unknown parameter of " + kind + " '" + id + "' (it has: " + (known.empty() ? "none" : known) +
                      ")");
    } catch (const PresetError& e) {
        throw PresetError(e.file(), e.field(),
                          listName + " " + std::to_string(listNumber) + " '" + id + "': " + e.reason());
    }
}
template <class NodeT>
void writeNodeSchedule(const NodeT& n, nlohmann::json& node) {
    if (!n.enabled) node["enabled"] = false;
    if (n.period != 1) node["period"] = n.period;
    if (n.phase != 0) node["phase"] = n.phase;
    if (n.start != 0) node["start"] = n.start;
    if (n.stop != kMaxIterations) node["stop"] = n.stop;
}
inline nlohmann::json vecJson(const vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); }
// A node: its block, its schedule and the parameters that differ from their defaults (floats as
// numbers, toggles as true/false, vectors as arrays). NodeT: Node or PlaneNode.
// {"params": ...} with the parameters that differ from their defaults (none: {}). NodeT: a
// Node, PlaneNode or SceneObject.
template <class NodeT>
nlohmann::json paramsOnlyJson(const NodeT& n) {
    nlohmann::json j = nlohmann::json::object();
    nlohmann::json params = nlohmann::json::object();
    for (size_t i = 0; i < n.block->params.size(); ++i) {
        const ParamDecl& d = n.block->params[i];
        if (d.type == ParamType::Toggle) {
            const bool on = n.values[i].x > 0.5;
            if (on != (d.defaultValue.x > 0.5)) params[std::string(d.name)] = on;
        } else if (d.type == ParamType::Float) {
            if (n.values[i].x != d.defaultValue.x) params[std::string(d.name)] = n.values[i].x;
        } else if (n.values[i] != d.defaultValue) {
            params[std::string(d.name)] = vecJson(n.values[i]);
        }
    }
    if (!params.empty()) j["params"] = params;
    return j;
}
template <class NodeT>
nlohmann::json nodeToJson(const NodeT& n) {
    nlohmann::json j = paramsOnlyJson(n);
    j["block"] = n.block->id;
    writeNodeSchedule(n, j);
    return j;
}
// The closing estimator at `path` runs once, after the loop.
template <class NodeT>
void checkEstimatorSchedule(const NodeT& n, const std::string& file, const std::string& path) {
    if (!n.enabled) throw PresetError(file, path + ".enabled", "the estimator cannot be disabled");
    if (n.period != 1) throw PresetError(file, path + ".period", "the estimator runs once, after the loop");
    if (n.windowed()) throw PresetError(file, path + ".start", "the estimator runs once, after the loop");
}
// The image size and samples of the "render" section.
void readImageSize(FieldReader& render, RenderSettings& s);
void writeImageSize(const RenderSettings& s, nlohmann::json& render);

// Writes only what differs from defaults, plus the format and version.
nlohmann::json presetToJson(const Preset& preset);
// The "formula" section alone: every field of the formula a render reads (nodes, objects,
// combined fractals, placement, custom blocks), as presetToJson writes it.
nlohmann::json formulaToJson(const Formula& formula);
std::string serializePreset(const Preset& preset);
// Saves atomically (temp file, fsync, rename) and keeps the previous version as PATH.bak: if
// the program is killed mid-save, PATH is the complete old or the complete new preset.
void savePresetFile(const std::filesystem::path& path, const Preset& preset);

// A short human-readable listing of the formula (for `fraktal check`).
std::string describeFormula(const Formula& f);

}  // namespace fraktal
