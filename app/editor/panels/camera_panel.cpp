// The camera tab: orbit / fly mode, field of view, position and target, reset view, and the
// saved view slots (undoable, saved with the preset).
#include <imgui.h>

#include <algorithm>
#include <string>

#include "app/editor/input/fly_speed.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/text_fit.hpp"
#include "core/scene/formula_fit.hpp"

namespace fraktal::editor {

void drawCameraTab(EditorState& s) {
    Camera& cam = s.doc.preset.camera;
    const Formula& f = s.doc.preset.formula;
    int mode = int(s.cameraControls.mode);
    ImGui::RadioButton("Orbit", &mode, int(CameraMode::Orbit));
    ImGui::SameLine();
    ImGui::RadioButton("Fly", &mode, int(CameraMode::Fly));
    ImGui::SameLine();
    ImGui::TextDisabled("(V over the viewport)");
    s.cameraControls.mode = CameraMode(mode);
    // Every line of text wraps at the panel's edge, and the fields leave their labels room.
    ImGui::PushTextWrapPos(0.0f);
    ImGui::PushItemWidth(-(ImGui::CalcTextSize("Speed per distance").x + ImGui::GetStyle().ItemInnerSpacing.x));
    if (s.cameraControls.mode == CameraMode::Orbit)
        ImGui::TextDisabled("Left drag: orbit. Right/middle drag: pan. Wheel: zoom.");
    else
        ImGui::TextDisabled(
            "W/A/S/D: move, Q/E: down/up, left drag: look, Shift: 4x. "
            "Speed follows the distance to the surface.");

    // A pinhole up to 120 degrees (wider stretches the edges); the wide projections to the whole sphere.
    const double fovLo = 5.0, fovHi = cam.projection == Projection::Perspective ? 120.0 : 360.0;
    const auto keyValue = [](const vec3& v) { return std::vector<double>{v.x, v.y, v.z}; };
    keyMarker(s, "camera.fovY", {cam.fovY});
    dragClamped("Field of view", &cam.fovY, 1, 0.2f, fovLo, fovHi, "%.1f deg");
    keyMarker(s, "camera.position", keyValue(cam.position));
    ImGui::DragScalarN("Position", ImGuiDataType_Double, &cam.position.x, 3, 0.01f, nullptr, nullptr, "%.3f");
    keyMarker(s, "camera.target", keyValue(cam.target));
    ImGui::DragScalarN("Target", ImGuiDataType_Double, &cam.target.x, 3, 0.01f, nullptr, nullptr, "%.3f");
    keyMarker(s, kCameraOrientationTarget, cameraOrientation(cam));
    ImGui::TextDisabled("Orientation (a key never flips)");
    if (ImGui::Button("Reset view")) cam = defaultViewFor(f, cam);
    noteWidgetRect(s.layout, "button:Reset view");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Shortcut: Home");
    // On the same line, so that the rows below keep their places; the combo takes what its label
    // and help marker leave.
    ImGui::SameLine();
    const ImGuiStyle& style = ImGui::GetStyle();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::CalcTextSize("Projection").x -
                            ImGui::CalcTextSize("(?)").x - style.ItemInnerSpacing.x - style.ItemSpacing.x);
    int projection = int(cam.projection);
    const char* projections[] = {"Perspective", "Fish eye", "Equirectangular"};
    if (ImGui::Combo("Projection", &projection, projections, IM_ARRAYSIZE(projections))) {
        cam.projection = Projection(projection);
        if (cam.projection == Projection::Perspective) cam.fovY = std::min(cam.fovY, 120.0);
    }
    checkComboFits("Projection", projections[projection]);
    noteWidgetRect(s.layout, "combo:Projection");
    helpMarker(
        "Perspective: a pinhole. Fish eye: the angle from the centre grows with the distance from it (a dome "
        "at 180 degrees). Equirectangular: longitude across, latitude up; a 2:1 image at 180 degrees is a 360 "
        "panorama. The wide projections have no depth of field.");

    sectionHeader("Fly speed");
    const DistanceAt de = s.eyeDistance.of(f);
    const double d = safeDistance(f, de, cam.position);
    ImGui::Text("Distance to the surface: %.4g", d);
    ImGui::Text("Fly speed: %.4g units/s", flySpeed(f, de, cam.position, s.cameraControls.fly));
    const double lo = 0.05, hi = 20.0;
    dragClamped("Speed per distance", &s.cameraControls.fly.speedPerDistance, 1, 0.01f, lo, hi, "%.2f /s",
                ImGuiSliderFlags_Logarithmic);

    sectionHeader("View slots");
    for (int i = 0; i < kViewSlots; ++i) {
        ImGui::PushID(i);
        auto& slot = s.doc.viewSlots[size_t(i)];
        ImGui::BeginDisabled(!slot);
        if (ImGui::Button(("Go to " + std::to_string(i + 1)).c_str(), ImVec2(90, 0))) cam = *slot;
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Shortcut: %d", i + 1);
        ImGui::SameLine();
        if (ImGui::Button("Store")) slot = cam;
        noteWidgetRect(s.layout, "button:Store " + std::to_string(i + 1));
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("Shortcut: Ctrl+%d", i + 1);
        ImGui::SameLine();
        ImGui::BeginDisabled(!slot);
        if (ImGui::Button("Clear")) slot.reset();
        noteWidgetRect(s.layout, "button:Clear " + std::to_string(i + 1));
        ImGui::EndDisabled();
        ImGui::PopID();
    }
    ImGui::PopItemWidth();
    ImGui::PopTextWrapPos();
}

}  // namespace fraktal::editor
