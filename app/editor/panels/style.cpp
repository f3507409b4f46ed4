// The editor's look: a dark, low-contrast theme so the fractal stays the brightest thing on
// screen, with rounded frames and an accent colour for selection.
#include <imgui.h>

#include "app/editor/panels/panels.hpp"

namespace fraktal::editor {

void applyEditorStyle(float scale) {
    ImGui::StyleColorsDark();
    ImGuiStyle& st = ImGui::GetStyle();
    st.WindowRounding = 0.0f;
    st.FrameRounding = 4.0f;
    st.GrabRounding = 4.0f;
    st.PopupRounding = 4.0f;
    st.TabRounding = 4.0f;
    st.ScrollbarRounding = 6.0f;
    st.WindowBorderSize = 0.0f;
    st.FramePadding = ImVec2(7, 4);
    st.ItemSpacing = ImVec2(8, 6);
    st.WindowPadding = ImVec2(10, 10);
    ImVec4* c = st.Colors;
    const ImVec4 accent(0.93f, 0.55f, 0.24f, 1.0f);
    c[ImGuiCol_WindowBg] = ImVec4(0.075f, 0.08f, 0.09f, 0.97f);
    c[ImGuiCol_PopupBg] = ImVec4(0.09f, 0.095f, 0.105f, 0.98f);
    c[ImGuiCol_MenuBarBg] = ImVec4(0.10f, 0.105f, 0.115f, 1.0f);
    c[ImGuiCol_TitleBg] = c[ImGuiCol_TitleBgActive] = ImVec4(0.10f, 0.105f, 0.115f, 1.0f);
    c[ImGuiCol_FrameBg] = ImVec4(0.15f, 0.16f, 0.18f, 1.0f);
    c[ImGuiCol_FrameBgHovered] = ImVec4(0.20f, 0.21f, 0.24f, 1.0f);
    c[ImGuiCol_FrameBgActive] = ImVec4(0.25f, 0.26f, 0.30f, 1.0f);
    c[ImGuiCol_Button] = ImVec4(0.17f, 0.18f, 0.20f, 1.0f);
    c[ImGuiCol_ButtonHovered] = ImVec4(0.26f, 0.27f, 0.30f, 1.0f);
    c[ImGuiCol_ButtonActive] = ImVec4(accent.x, accent.y, accent.z, 0.7f);
    c[ImGuiCol_Header] = ImVec4(accent.x, accent.y, accent.z, 0.28f);
    c[ImGuiCol_HeaderHovered] = ImVec4(accent.x, accent.y, accent.z, 0.40f);
    c[ImGuiCol_HeaderActive] = ImVec4(accent.x, accent.y, accent.z, 0.55f);
    c[ImGuiCol_Tab] = ImVec4(0.14f, 0.15f, 0.17f, 1.0f);
    c[ImGuiCol_TabHovered] = ImVec4(accent.x, accent.y, accent.z, 0.5f);
    c[ImGuiCol_TabActive] = ImVec4(accent.x * 0.6f, accent.y * 0.6f, accent.z * 0.6f, 1.0f);
    c[ImGuiCol_CheckMark] = accent;
    c[ImGuiCol_SliderGrab] = accent;
    c[ImGuiCol_SliderGrabActive] = ImVec4(1.0f, 0.7f, 0.4f, 1.0f);
    c[ImGuiCol_Separator] = ImVec4(0.22f, 0.23f, 0.26f, 1.0f);
    c[ImGuiCol_ResizeGrip] = ImVec4(0, 0, 0, 0);
    c[ImGuiCol_DragDropTarget] = accent;
    st.ScaleAllSizes(scale);
}

}  // namespace fraktal::editor
