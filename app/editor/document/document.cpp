#include "app/editor/document/document.hpp"

#include <algorithm>

namespace fraktal::editor {

using nlohmann::json;

namespace {

json vecJson(const vec3& v) { return json::array({v.x, v.y, v.z}); }

vec3 vecFrom(const json& j, const vec3& fallback) {
    if (!j.is_array() || j.size() != 3) return fallback;
    for (const json& e : j)
        if (!e.is_number()) return fallback;
    return {j[0].get<double>(), j[1].get<double>(), j[2].get<double>()};
}

json cameraJson(const Camera& c) {
    return {{"position", vecJson(c.position)}, {"target", vecJson(c.target)}, {"up", vecJson(c.up)}, {"fovY", c.fovY}};
}

Camera cameraFrom(const json& j) {
    Camera c;
    c.position = vecFrom(j.value("position", json()), c.position);
    c.target = vecFrom(j.value("target", json()), c.target);
    c.up = vecFrom(j.value("up", json()), c.up);
    if (j.contains("fovY") && j["fovY"].is_number()) c.fovY = std::clamp(j["fovY"].get<double>(), 1.0, 170.0);
    return c;
}

json editorSection(const Document& d) {
    json slots = json::array();
    for (const auto& slot : d.viewSlots) slots.push_back(slot ? cameraJson(*slot) : json());
    return {{"view", viewSettingsToJson(d.view)}, {"viewSlots", slots}};
}

}  // namespace

json viewSettingsToJson(const ViewSettings& s) {
    return {{"stepsPerFrame", s.stepsPerFrame},
            {"renderScale", s.renderScale},
            {"reprojection", s.reprojection},
            {"aaCap", s.aaCap},
            {"coneTile", s.coneTile},
            {"maxCarryFrames", s.maxCarryFrames},
            {"motionFilter", s.motionFilter},
            {"motionFilterRadius", s.motionFilterRadius},
            {"coarseHits", s.coarseHits},
            {"frameTimeTargetMs", s.frameTimeTargetMs},
            {"motionMinScale", s.motionMinScale},
            {"renderMode", s.pathTraceAtRest ? "path" : "fast"},
            {"pathSppCap", s.pathSppCap}};
}

ViewSettings viewSettingsFromJson(const json& j) {
    ViewSettings s;
    if (!j.is_object()) return s;
    auto number = [&](const char* key, double fallback, double lo, double hi) {
        const json& v = j.value(key, json());
        return v.is_number() ? std::clamp(v.get<double>(), lo, hi) : fallback;
    };
    const json& reprojection = j.value("reprojection", json());
    s.stepsPerFrame = int(number("stepsPerFrame", s.stepsPerFrame, 1, 1000));
    s.renderScale = number("renderScale", s.renderScale, 0.1, 1.0);
    s.frameTimeTargetMs = number("frameTimeTargetMs", s.frameTimeTargetMs, 0.0, 1000.0);
    s.motionMinScale = number("motionMinScale", s.motionMinScale, 1.0 / 16.0, 1.0);
    if (reprojection.is_boolean()) s.reprojection = reprojection.get<bool>();
    s.aaCap = int(number("aaCap", s.aaCap, 1, 256));
    s.coneTile = int(number("coneTile", s.coneTile, 0, 64));
    s.maxCarryFrames = int(number("maxCarryFrames", s.maxCarryFrames, 0, 1000));
    const json& motionFilter = j.value("motionFilter", json());
    if (motionFilter.is_boolean()) s.motionFilter = motionFilter.get<bool>();
    s.motionFilterRadius =
        number("motionFilterRadius", s.motionFilterRadius, viewport::ViewportOptions::kMinFilterRadius,
               viewport::ViewportOptions::kMaxFilterRadius);
    const json& coarseHits = j.value("coarseHits", json());
    if (coarseHits.is_boolean()) s.coarseHits = coarseHits.get<bool>();
    s.pathTraceAtRest = j.value("renderMode", json()) == json("path");
    s.pathSppCap = int(number("pathSppCap", s.pathSppCap, 1, 65536));
    return s;
}

std::string fingerprint(const Document& d) {
    if (d.plane) return planePresetToJson(*d.plane).dump();
    json j = presetToJson(d.preset);
    j["editor"] = editorSection(d);
    return j.dump();
}

std::string documentFileText(const Document& d) {
    if (d.plane) return serializePlanePreset(*d.plane);
    Document withSection = d;
    storeEditorSection(withSection);
    return serializePreset(withSection.preset);
}

void storeEditorSection(Document& d) { d.preset.extra["editor"] = editorSection(d); }

void loadEditorSection(Document& d) {
    const json& e = d.preset.extra.value("editor", json());
    if (!e.is_object()) return;
    d.view = viewSettingsFromJson(e.value("view", json()));
    const json& slots = e.value("viewSlots", json());
    if (!slots.is_array()) return;
    for (size_t i = 0; i < slots.size() && i < d.viewSlots.size(); ++i)
        d.viewSlots[i] = slots[i].is_object() ? std::optional<Camera>(cameraFrom(slots[i])) : std::nullopt;
}

}  // namespace fraktal::editor
