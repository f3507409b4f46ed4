// The right-hand panel: camera, render and shading settings and the preset browser as tabs (ImGui 1.86 has
// no docking, so panels are fixed columns whose widths the ini file remembers).
#include <imgui.h>

#include "app/editor/panels.hpp"

namespace fraktal::editor {

namespace {
// Selects the tab named by `--tab` (or a command) once.
ImGuiTabItemFlags selectIf(const EditorState& s, const char* tab) {
    return s.panels.selectTab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
}
}  // namespace

void drawSidebar(EditorState& s) {
    if (!s.panels.sidebar) return;
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const float height = vp->WorkSize.y;
    ImGui::SetNextWindowSizeConstraints(ImVec2(260, height), ImVec2(vp->WorkSize.x * 0.45f, height));
    ImGui::SetNextWindowSize(ImVec2(s.layout.rightWidth, height), ImGuiCond_FirstUseEver);
    // Anchored to the right edge: its width comes from last frame (or the ini file).
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x + vp->WorkSize.x, vp->WorkPos.y), ImGuiCond_Always, ImVec2(1, 0));
    ImGui::Begin("Scene", &s.panels.sidebar, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
    s.layout.rightWidth = ImGui::GetWindowWidth();
    if (ImGui::BeginTabBar("scene_tabs")) {
        if (ImGui::BeginTabItem("Camera", nullptr, selectIf(s, "Camera"))) {
            drawCameraTab(s);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Render", nullptr, selectIf(s, "Render"))) {
            drawRenderTab(s);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Shading", nullptr, selectIf(s, "Shading"))) {
            drawShadingTab(s);
            ImGui::EndTabItem();
        }
        if (ImGui::BeginTabItem("Presets", nullptr, selectIf(s, "Presets"))) {
            drawPresetsTab(s);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    s.panels.selectTab.clear();
    ImGui::End();
}

}  // namespace fraktal::editor
