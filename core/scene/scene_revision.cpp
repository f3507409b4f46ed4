#include "core/scene/scene_revision.hpp"

#include <cassert>
#include <utility>

namespace fraktal::scene {

using nlohmann::json;

const std::vector<IgnoredField>& fieldsNoRenderReads() {
    static const std::vector<IgnoredField> fields = {
        {"format", "the file's kind, checked on load"},
        {"version", "the file's format version, checked on load"},
        {"name", "shown in the title and the preset browser, never rendered"},
        {"description", "shown in the preset browser, never rendered"},
        {"animation", "keys: renderers get the document as evaluated at the timeline's frame"},
        {"editor", "the editor's own layout and view state"},
        {"render.width", "the export's image size: the viewport renders at its own size"},
        {"render.height", "the export's image size: the viewport renders at its own size"},
        {"render.spp", "the export's samples: the viewport has its own sample cap"},
    };
    return fields;
}

namespace {

// The camera's pose and projection: what reprojection carries the image through.
constexpr const char* kPoseFields[] = {"position", "target", "up", "fovY", "projection", "flipVertical"};
// The display transform: applied to the linear image at display.
constexpr const char* kDisplayFields[] = {"display", "view", "exposure"};

void erasePath(json& j, const std::string& path) {
    const size_t dot = path.find('.');
    if (dot == std::string::npos) {
        j.erase(path);
        return;
    }
    const std::string section = path.substr(0, dot);
    if (!j.contains(section) || !j[section].is_object()) return;
    j[section].erase(path.substr(dot + 1));
    if (j[section].empty()) j.erase(section);
}

}  // namespace

SceneRevision sceneRevision(const Preset& preset) { return sceneRevision(preset, preset.formula.structureKey()); }

SceneRevision sceneRevision(const Preset& preset, std::string structure) {
    assert(structure == preset.formula.structureKey());
    SceneRevision r;
    r.structure = std::move(structure);
    r.camera = preset.camera;
    json j = presetToJson(preset);
    for (const IgnoredField& f : fieldsNoRenderReads()) erasePath(j, f.path);
    // The camera section keeps the lens (aperture, focus, blades): a change restarts the samples.
    if (j.contains("camera"))
        for (const char* field : kPoseFields) j["camera"].erase(field);
    json display = json::object();
    if (j.contains("colorManagement")) {
        json& cm = j["colorManagement"];
        for (const char* field : kDisplayFields)
            if (cm.contains(field)) {
                display[field] = cm[field];
                cm.erase(field);
            }
        if (cm.empty()) j.erase("colorManagement");
    }
    r.values = j.dump();
    r.display = display.dump();
    return r;
}

SceneChange sceneChange(const SceneRevision* before, const SceneRevision& after) {
    if (!before) return {true, true, true, true};
    SceneChange c;
    c.structure = before->structure != after.structure;
    c.values = c.structure || before->values != after.values;
    c.camera = before->camera != after.camera;
    c.display = before->display != after.display;
    return c;
}

}  // namespace fraktal::scene
