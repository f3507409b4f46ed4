// The render tab: the viewport's march budget, progressive AA, shading and display exposure.
#include <imgui.h>

#include "app/editor/panels.hpp"
#include "app/editor/param_widgets.hpp"

namespace fraktal::editor {

void drawRenderTab(EditorState& s) {
    ViewSettings& v = s.doc.view;
    sectionHeader("Viewport");
    ImGui::DragInt("Steps per ray", &v.maxSteps, 1.0f, 8, 2000, "%d", ImGuiSliderFlags_AlwaysClamp);
    helpMarker("Sphere-tracing steps per pixel per frame. On a CPU renderer every step shows in the frame time.");
    const double scaleLo = 0.1, scaleHi = 1.0;
    ImGui::DragScalar("Resolution", ImGuiDataType_Double, &v.renderScale, 0.005f, &scaleLo, &scaleHi, "%.2f x",
                      ImGuiSliderFlags_AlwaysClamp);
    helpMarker("Share of the window's pixels the viewport renders (upscaled for display).");
    ImGui::Checkbox("Accumulate / reproject", &v.reprojection);
    helpMarker("Keep refining the image while nothing changes. Off: every frame starts again.");
    ImGui::BeginDisabled(!v.reprojection);
    ImGui::DragInt("AA cap (spp)", &v.aaCap, 0.1f, 1, 256, "%d", ImGuiSliderFlags_AlwaysClamp);
    ImGui::EndDisabled();
    helpMarker("Samples per pixel after which the viewport stops rendering (converged).");

    sectionHeader("Shading");
    ImGui::DragScalarN("Light direction", ImGuiDataType_Double, &v.lightDirection.x, 3, 0.01f, nullptr, nullptr,
                       "%.2f");
    ImGui::Checkbox("Shadows", &v.shadows);
    ImGui::SameLine();
    ImGui::Checkbox("Ambient occlusion", &v.ambientOcclusion);
    const double fogLo = 0.0, fogHi = 10.0;
    ImGui::DragScalar("Fog", ImGuiDataType_Double, &v.fog, 0.01f, &fogLo, &fogHi, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    helpMarker("Density of the distance fog, per bound radius travelled.");
    ImGui::Combo("Palette", &v.palette, kPaletteNames, kPaletteCount);
    helpMarker("Orbit-trap colouring (seed 3.3): the orbit's closest approach to the origin and the planes.");

    sectionHeader("Display");
    const double expLo = -10.0, expHi = 10.0;
    ImGui::DragScalar("Exposure", ImGuiDataType_Double, &v.exposure, 0.02f, &expLo, &expHi, "%+.2f EV",
                      ImGuiSliderFlags_AlwaysClamp);
    helpMarker("Applied at display only: the rendered data stays linear.");
    ImGui::TextDisabled("View: sRGB (OCIO display/view follows with core/color)");
}

}  // namespace fraktal::editor
