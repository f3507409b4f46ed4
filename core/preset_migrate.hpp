// Migration of presets written by older versions of the format: an ordered list of pure steps,
// one per version (vN -> vN+1, over the JSON document), run before the document is read. Each step
// says in words what it changed (a note for the user; not an error) and which fields it moved,
// so that an error in a migrated file can still name the field as it stands in the file.
// What each version changed: presets/README.md, "Versions".
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace fraktal {

// What one step did to one document.
struct MigrationStepResult {
    std::string note;  // for the user, e.g. "render.exposure moved to colorManagement.exposure"
    // Fields it moved: (field path now, field path in the step's input).
    std::vector<std::pair<std::string, std::string>> moved;
};

// One step: migrates a document of version `fromVersion` to `fromVersion + 1`. It must accept
// any JSON object (a malformed file is refused by the reader afterwards, not here) and must not
// set "version" (migratePreset does).
struct PresetMigration {
    int fromVersion;
    MigrationStepResult (*migrate)(nlohmann::json& preset);
};

// What migrating one document did, over all steps.
struct MigrationReport {
    std::vector<std::string> notes;  // one per step run: "version 1 -> 2: ..."
    // Fields moved: (field path now, field path in the file as it was read), chained over steps.
    std::vector<std::pair<std::string, std::string>> moved;

    // `field` (a path in the migrated document, maybe inside a moved field) as it is written in
    // the original file.
    std::string fieldInFile(const std::string& field) const;
};

// The steps of this build, ordered by fromVersion: together they lead from version 1 to
// kPresetVersion (core/preset.hpp).
std::span<const PresetMigration> presetMigrations();

// Runs the steps from `fromVersion` up to `toVersion` in order, setting "version" after each.
// `preset` must be an object. Throws std::logic_error when a step is missing from `steps` (a
// bug of this build, not of the file).
MigrationReport migratePreset(nlohmann::json& preset, int fromVersion, int toVersion,
                              std::span<const PresetMigration> steps);

}  // namespace fraktal
