// The right-hand panel: camera, render and shading settings and the preset browser as tabs (ImGui 1.86 has
// no docking, so panels are fixed columns whose widths the ini file remembers). A 2D document
// shows its view, render (colour) and colouring settings and the browser.
#include <imgui.h>

#include <utility>

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
    // A 2D document shows its view rectangle instead of a camera, its colouring instead of shading.
    using Tab = std::pair<const char*, void (*)(EditorState&)>;
    const Tab scene[] = {
        {"Camera", drawCameraTab}, {"Render", drawRenderTab}, {"Shading", drawShadingTab}, {"Presets", drawPresetsTab}};
    const Tab plane[] = {{"View", drawPlaneViewTab},
                         {"Render", drawRenderTab},
                         {"Colouring", drawPlaneColouringTab},
                         {"Presets", drawPresetsTab}};
    if (ImGui::BeginTabBar(s.doc.plane ? "plane_tabs" : "scene_tabs")) {
        for (const auto& [name, draw] : s.doc.plane ? plane : scene) {
            if (!ImGui::BeginTabItem(name, nullptr, selectIf(s, name))) continue;
            draw(s);
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    s.panels.selectTab.clear();
    ImGui::End();
}

}  // namespace fraktal::editor
