#include "core/preset_migrate.hpp"

#include <stdexcept>

namespace fraktal {

using nlohmann::json;

namespace {

// Version 1 -> 2: the colour-management settings leave "render" for a section of their own,
// "colorManagement". Version 1 mixed them with what is rendered (size, samples, marching),
// although they change only how the scene-linear result is stored and displayed (the EXR stays
// scene-linear; display, view and exposure apply to previews, as in tev and Blender's "Color
// Management" panel); and in 2D presets "render.view" (an OCIO view) sat beside the top-level
// "view" (the part of the plane shown), one name for two unrelated things.
constexpr const char* kColorManagementKeys[] = {"workingSpace", "display", "view", "exposure"};

MigrationStepResult moveColorManagementOutOfRender(json& preset) {
    MigrationStepResult result;
    auto render = preset.find("render");
    if (render != preset.end() && render->is_object()) {
        if (!preset.contains("colorManagement")) preset["colorManagement"] = json::object();
        json& color = preset["colorManagement"];
        // A malformed file (a colorManagement that is not an object, or that already holds the
        // field) keeps its render field: the reader then refuses it as an unknown field there.
        for (const char* key : kColorManagementKeys) {
            if (!render->contains(key) || !color.is_object() || color.contains(key)) continue;
            color[key] = std::move((*render)[key]);
            render->erase(key);
            result.moved.emplace_back(std::string("colorManagement.") + key, std::string("render.") + key);
        }
        if (color.is_object() && color.empty()) preset.erase("colorManagement");
        if (render->empty()) preset.erase(render);
    }
    if (result.moved.empty()) {
        result.note =
            "nothing to change (version 2 moved the colour-management fields out of render; this file "
            "sets none)";
    } else {
        std::string fields;
        for (const auto& [now, before] : result.moved) fields += (fields.empty() ? "" : ", ") + before;
        result.note = fields + " moved to the new colorManagement section";
    }
    return result;
}

// Version 2 -> 3: the optional "animation" section is new; nothing already in a file changes.
MigrationStepResult addAnimationSection(json&) {
    return {"nothing to change (version 3 added the optional animation section)", {}};
}

constexpr PresetMigration kPresetMigrations[] = {
    {1, &moveColorManagementOutOfRender},
    {2, &addAnimationSection},
};

// `field` equals `path` or lies inside it.
bool isWithin(const std::string& field, const std::string& path) {
    return field.compare(0, path.size(), path) == 0 &&
           (field.size() == path.size() || field[path.size()] == '.' || field[path.size()] == '[');
}

}  // namespace

std::span<const PresetMigration> presetMigrations() { return kPresetMigrations; }

std::string MigrationReport::fieldInFile(const std::string& field) const {
    for (const auto& [now, before] : moved)
        if (isWithin(field, now)) return before + field.substr(now.size());
    return field;
}

MigrationReport migratePreset(json& preset, int fromVersion, int toVersion, std::span<const PresetMigration> steps) {
    MigrationReport report;
    for (int version = fromVersion; version < toVersion; ++version) {
        const PresetMigration* step = nullptr;
        for (const PresetMigration& s : steps)
            if (s.fromVersion == version) step = &s;
        if (!step) throw std::logic_error("no preset migration from version " + std::to_string(version));
        MigrationStepResult result = step->migrate(preset);
        preset["version"] = version + 1;
        report.notes.push_back("version " + std::to_string(version) + " -> " + std::to_string(version + 1) + ": " +
                               result.note);
        // Chain the moves: a field moved again is traced back to where the file had it, and its
        // earlier place no longer names it.
        std::vector<std::pair<std::string, std::string>> traced;
        for (const auto& [now, before] : result.moved) traced.emplace_back(now, report.fieldInFile(before));
        for (const auto& move : result.moved)
            std::erase_if(report.moved, [&](const auto& m) { return isWithin(m.first, move.second); });
        report.moved.insert(report.moved.end(), traced.begin(), traced.end());
    }
    return report;
}

}  // namespace fraktal
