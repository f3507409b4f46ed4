// The View tab of a 2D document, in place of the 3D Camera tab: the view rectangle (centre and
// width in the plane, double precision), how to navigate, "reset view", and the preset's
// description (what the formula does, in the seed's terms).
#include <imgui.h>

#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/widgets/param_widgets.hpp"

namespace fraktal::editor {

void drawPlaneViewTab(EditorState& s) {
    if (!s.doc.plane) return;
    PlaneViewRect& v = s.doc.plane->view;
    sectionHeader("View");
    double centre[2] = {v.center.x, v.center.y};
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.7f);
    if (ImGui::InputScalarN("Centre", ImGuiDataType_Double, centre, 2, nullptr, nullptr, "%.17g"))
        v.center = real2(centre[0], centre[1]);
    helpMarker("The plane point at the middle of the image.");
    const double lo = 1e-300, hi = 1e4;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.7f);
    dragClamped("Width", &v.width, 1, 0.002f * float(v.width), lo, hi, "%.6g", ImGuiSliderFlags_Logarithmic);
    helpMarker("The width of the image in plane units. With fp64 the set keeps its structure down to about 1e-13.");
    if (ImGui::Button("Reset view (Home)")) resetPlaneView(s);
    ImGui::Text("Zoom %.3gx of the opened view", s.planeHome.width / v.width);
    sectionHeader("Navigate");
    ImGui::TextDisabled("Drag: pan.  Wheel: zoom about the cursor.");
    ImGui::TextDisabled("The image refines while nothing changes.");
    sectionHeader("About this preset");
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(s.doc.plane->description.empty() ? "(no description)" : s.doc.plane->description.c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace fraktal::editor
