// The Lights tab: the preset's print-quality lighting (core/lighting.hpp) that the
// path-traced mode renders: the list of lights, the environment map, the thin lens and the path
// tracer's settings. The fast viewport lights with the Shading tab, so the lights and the map show
// in `fraktal render --mode path` (and the viewport's path-traced mode); the lens's depth of field
// shows everywhere, in the fast viewport once it rests. Every edit is an edit of the document: the
// editor commits one undo step per finished gesture (editor.cpp).
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // ClearActiveID
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <iterator>

#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/widgets/node_list_widgets.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/setting_widgets.hpp"
#include "core/image/environment.hpp"

namespace fraktal::editor {

namespace {

// The last item's window rectangle under `name`, for the state file.
void record(LightsPanel& p, const std::string& name) {
    const ImVec2 a = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
    p.widgets[name] = {a.x, a.y, size.x, size.y};
}

// The same for a widget whose help marker follows it on its line.
void recordWithHelp(LightsPanel& p, const std::string& name, const char* help) {
    record(p, name);
    if (help) helpMarker(help);
}

void say(LightsPanel& p, std::string text, bool error) {
    p.message = std::move(text);
    p.messageIsError = error;
}

std::vector<double> keyValue(const vec3& v) { return {v.x, v.y, v.z}; }

bool positionEdit(const char* label, vec3& v) {
    double x[3] = {v.x, v.y, v.z};
    if (!dragClamped(label, x, 3, 0.01f, -1e4, 1e4, "%.3f")) return false;  // the preset reader's range
    v = vec3(x[0], x[1], x[2]);
    return true;
}

// A rectangle's frame needs `up` off its normal (the preset reader refuses it otherwise).
bool rectFrameValid(const Light& l) { return length(glm::cross(normalize(l.normal), l.up)) >= 1e-6; }

// Switching type keeps colour, intensity and place; the size is made valid for the new type.
void changeType(Light& l, LightType type) {
    if (l.type == type) return;
    const Light fresh = newLight(type);
    l.type = type;
    if (type == LightType::Directional)
        l.size = std::min(l.size, 45.0);
    else if (type == LightType::Rect && l.size <= 0.0)
        l.size = fresh.size;
    if (type == LightType::Rect && !rectFrameValid(l)) {
        l.normal = fresh.normal;
        l.up = fresh.up;
    }
}

void drawLightSettings(EditorState& s, LightsPanel& p, Light& l, int index) {
    const std::string target = "lights[" + std::to_string(index) + "].";
    int type = int(l.type);
    // The table is in the enum's order, so an item's index is its LightType.
    const char* labels[std::size(kLightTypeNames)];
    for (size_t i = 0; i < std::size(kLightTypeNames); ++i) labels[i] = kLightTypeNames[i].label;
    if (ImGui::Combo("Type", &type, labels, int(std::size(labels)))) changeType(l, kLightTypeNames[type].type);
    keyMarker(s, target + "color", keyValue(l.color));
    colorEdit("Colour", l.color, nullptr);
    recordWithHelp(p, "light.color", "Linear Rec.709; multiplies the intensity.");
    keyMarker(s, target + "intensity", {l.intensity});
    const char* intensityHelp = l.type == LightType::Directional ? "Irradiance on a surface facing the light."
                                : l.type == LightType::Sphere
                                    ? "Radiant intensity: irradiance at distance 1, falling off as 1/d^2."
                                    : "Radiance of the rectangle's surface.";
    dragDouble("Intensity", l.intensity, 0.0, 1e6, 0.01f, "%.3f", nullptr);
    recordWithHelp(p, "light.intensity", intensityHelp);
    if (l.type == LightType::Directional) {
        keyMarker(s, target + "direction", keyValue(l.direction));
        directionEdit("Direction", l.direction, "Toward the light (normalised on use).");
        keyMarker(s, target + "size", {l.size});
        dragDouble("Angular radius", l.size, 0.0, 45.0, 0.01f, "%.2f deg", nullptr);
        recordWithHelp(p, "light.size", "0: hard shadows; the sun is 0.27 degrees.");
        return;
    }
    keyMarker(s, target + "position", keyValue(l.position));
    positionEdit("Position", l.position);
    record(p, "light.position");
    if (l.type == LightType::Sphere) {
        keyMarker(s, target + "size", {l.size});
        dragDouble("Radius", l.size, 0.0, 100.0, 0.005f, "%.3f", nullptr);
        recordWithHelp(p, "light.size", "0: a point light (hard shadows).");
        return;
    }
    keyMarker(s, target + "size", {l.size});
    dragDouble("Width", l.size, 0.001, 100.0, 0.005f, "%.3f", nullptr);
    recordWithHelp(p, "light.size", nullptr);
    keyMarker(s, target + "height", {l.height});
    dragDouble("Height", l.height, 0.001, 100.0, 0.005f, "%.3f", nullptr);
    recordWithHelp(p, "light.height", "The extent along Up.");
    Light edited = l;
    if (directionEdit("Normal", edited.normal, "The side the rectangle emits toward.") ||
        directionEdit("Up", edited.up, "The direction of the height edge (not along the normal).")) {
        if (rectFrameValid(edited))
            l = edited;
        else
            say(p, "A rectangle's Up must not lie along its normal.", true);
    }
}

void drawLightList(EditorState& s, Lighting& lighting, LightsPanel& p) {
    sectionHeader("Lights");
    std::vector<Light>& lights = lighting.lights;
    const int count = int(lights.size());
    p.selected = std::clamp(p.selected, 0, std::max(count - 1, 0));
    if (lights.empty()) ImGui::TextDisabled("No lights: only the environment lights the path-traced image.");
    for (int i = 0; i < count; ++i) {
        ImGui::PushID(i);
        Light& l = lights[size_t(i)];
        ImGui::Checkbox("##on", &l.enabled);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("On / off");
        record(p, "lights[" + std::to_string(i) + "].enabled");
        ImGui::SameLine();
        char label[96];
        std::snprintf(label, sizeof label, "%d  %s  %.3g%s", i + 1, lightTypeNames(l.type).label, l.intensity,
                      l.enabled ? "" : "  (off)");
        if (ImGui::Selectable(label, p.selected == i)) p.selected = i;
        record(p, "lights[" + std::to_string(i) + "]");
        ImGui::PopID();
    }
    if (ImGui::Button("Add light")) ImGui::OpenPopup("add_light");
    record(p, "addLight");
    if (ImGui::BeginPopup("add_light")) {
        for (const LightTypeNames& names : kLightTypeNames) {
            const LightType type = names.type;
            const std::string name = names.label;
            if (ImGui::Selectable(name.c_str())) {
                if (std::string refused = addLight(lighting, type); refused.empty()) {
                    p.selected = int(lights.size()) - 1;
                    say(p, "", false);
                } else {
                    say(p, refused, true);
                }
            }
            record(p, "addLight." + name);
        }
        ImGui::EndPopup();
    }
    ImGui::BeginDisabled(lights.empty());
    ImGui::SameLine();
    if (ImGui::Button("Duplicate")) {
        if (std::string refused = duplicateLight(lighting, p.selected); refused.empty()) {
            ++p.selected;
            say(p, "", false);
        } else {
            say(p, refused, true);
        }
    }
    record(p, "duplicateLight");
    ImGui::SameLine();
    if (ImGui::Button("Remove") && removeLight(lighting, p.selected)) {
        p.selected = std::max(p.selected - 1, 0);
        say(p, "", false);
    }
    record(p, "removeLight");
    ImGui::EndDisabled();
    if (!lights.empty()) {
        ImGui::PushID("light");
        drawLightSettings(s, p, lights[size_t(p.selected)], p.selected);
        ImGui::PopID();
    }
}

// A typed path: relative to the preset's folder, as the preset format resolves it.
void applyTypedMap(EditorState& s, LightsPanel& p) {
    if (p.mapField.empty()) {
        s.doc.preset.lighting.environment.map.clear();
        say(p, "", false);
        return;
    }
    chooseEnvironmentMap(s, resolveEnvironmentPath(p.mapField, s.file.path.string()));
}

void drawEnvironment(EditorState& s, LightsPanel& p) {
    sectionHeader("Environment");
    EnvironmentSettings& e = s.doc.preset.lighting.environment;
    // The field follows the document (open, undo) but keeps what is being typed.
    if (e.map != p.syncedMap) p.mapField = p.syncedMap = e.map;
    ImGui::InputTextWithHint("Map", "equirectangular .exr", &p.mapField);
    // Enter from the window's key events (ImGui 1.86 misses a tap shorter than a frame), or
    // leaving the field after typing, applies the path.
    const bool enter =
        ImGui::IsItemActive() && std::any_of(s.keyPresses.begin(), s.keyPresses.end(), [](const KeyPress& k) {
            return k.key == GLFW_KEY_ENTER || k.key == GLFW_KEY_KP_ENTER;
        });
    if (enter) ImGui::ClearActiveID();
    if (enter || (ImGui::IsItemDeactivatedAfterEdit() && p.mapField != e.map)) applyTypedMap(s, p);
    record(p, "environment.map");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Relative to the preset's folder; Enter applies it.");
    if (ImGui::Button("Browse...")) s.dialogs.environmentMap = true;
    record(p, "environment.browse");
    ImGui::SameLine();
    ImGui::BeginDisabled(!e.active());
    if (ImGui::Button("No map")) e.map.clear();
    ImGui::EndDisabled();
    if (!e.active()) {
        ImGui::TextDisabled("No map: intensity, rotation and background need one.");
        return;
    }
    keyMarker(s, "environment.intensity", {e.intensity});
    dragDouble("Map intensity", e.intensity, 0.0, 1e6, 0.01f, "%.3f", "How brightly the map lights the scene.");
    keyMarker(s, "environment.rotation", {e.rotation});
    dragDouble("Rotation", e.rotation, -360.0, 360.0, 0.5f, "%.1f deg", "Turns the map about the vertical axis.");
    ImGui::Checkbox("Visible as background", &e.visible);
    helpMarker("Off: the map lights the scene but camera rays see the Shading tab's background.");
    ImGui::TextDisabled("Colour space: %s", e.colorSpace.c_str());
}

void drawLens(EditorState& s, LightsPanel& p) {
    sectionHeader("Lens");
    ThinLens& lens = s.doc.preset.lighting.lens;
    dragDouble("Aperture radius", lens.apertureRadius, 0.0, 10.0, 0.001f, "%.4f", nullptr);
    recordWithHelp(p, "lens.aperture", "World units; 0: a pinhole camera, no depth of field.");
    const Camera& cam = s.doc.preset.camera;
    if (!lens.enabled()) {
        p.pickFocus = false;
        ImGui::TextDisabled("No depth of field: a radius above 0 gives it.");
        return;
    }
    dragDouble("Focus distance", lens.focusDistance, 0.0, 1e5, 0.01f, "%.3f", nullptr);
    recordWithHelp(p, "lens.focusDistance", "Along the view axis; 0: the camera target's distance.");
    if (lens.focusDistance == 0.0) ImGui::TextDisabled("Focus on the target: %.3f", viewAxisDistance(cam, cam.target));
    // 0 (round) or 3..16 blades, as the preset stores them.
    constexpr const char* kBlades[] = {"round", "3",  "4",  "5",  "6",  "7",  "8", "9",
                                       "10",    "11", "12", "13", "14", "15", "16"};
    int blades = lens.blades < 3 ? 0 : std::min(lens.blades, 16) - 2;
    if (ImGui::Combo("Blades", &blades, kBlades, int(std::size(kBlades)))) lens.blades = blades == 0 ? 0 : blades + 2;
    if (ImGui::Button(p.pickFocus ? "Click the object..." : "Pick focus")) p.pickFocus = !p.pickFocus;
    record(p, "lens.pickFocus");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(p.pickFocus ? "Click again to cancel" : "Or Ctrl+click the viewport");
}

void drawPathTrace(LightsPanel& p, PathTraceSettings& t) {
    sectionHeader("Path tracer");
    dragInt("Bounces", t.bounces, 0, 16, 0.05f, nullptr);
    recordWithHelp(p, "pathTrace.bounces", "Surface interactions after the first hit.");
    dragDouble("Roughness", t.roughness, 0.02, 1.0, 0.002f, "%.3f",
               "How blurred the glossy reflections are: low is mirror-like, 1 is matte.");
    dragDouble("Specular", t.specular, 0.0, 1.0, 0.002f, "%.3f", "How much light the surface reflects seen face on.");
    dragDouble("Emission", t.emission, 0.0, 1e4, 0.01f, "%.3f", "The surface colour glows with this factor.");
}

}  // namespace

void chooseEnvironmentMap(EditorState& s, const std::filesystem::path& file) {
    LightsPanel& p = s.lights;
    if (std::string problem = environmentMapProblem(file); !problem.empty()) {
        say(p, "Environment map not changed: " + problem, true);
        return;
    }
    s.doc.preset.lighting.environment.map = environmentMapValue(file, s.file.path);
    say(p, "", false);
}

void drawLightsTab(EditorState& s) {
    LightsPanel& p = s.lights;
    p.widgets.clear();
    Lighting& lighting = s.doc.preset.lighting;
    // One line, the rest in its help: at 1280x800 every line here pushes the light's settings down.
    ImGui::TextDisabled("Lights of path-traced images");
    ImGui::SameLine();
    helpMarker(
        "The export's Path traced mode and the viewport's Path traced at rest (Render tab) use these lights. The "
        "fast viewport is lit by the Shading tab.");
    ImGui::PushTextWrapPos(0.0f);
    // Every line of text below wraps at the panel's edge.
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    drawLightList(s, lighting, p);
    drawEnvironment(s, p);
    drawLens(s, p);
    drawPathTrace(p, lighting.pathTrace);
    ImGui::PopItemWidth();
    ImGui::PopTextWrapPos();
    if (!p.message.empty()) {
        ImGui::Spacing();
        ImGui::PushTextWrapPos(0.0f);
        if (p.messageIsError)
            ImGui::TextColored(kErrorColor, "%s", p.message.c_str());
        else
            ImGui::TextUnformatted(p.message.c_str());
        ImGui::PopTextWrapPos();
        record(p, "message");
    }
}

}  // namespace fraktal::editor
