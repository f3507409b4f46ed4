// The side column and its lower panel, Scene: camera, render, shading and lighting settings and
// the preset browser as tabs (ImGui 1.86 has no docking, so the panels are fixed windows in one column on the
// left whose width and split the ini file remembers). A 2D document shows its view, render
// (colour) and colouring settings and the browser.
#include <imgui.h>
#include <imgui_internal.h>  // MarkIniSettingsDirty, BringWindowToDisplayBack

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

#include "app/editor/panels/panels.hpp"
#include "app/editor/widgets/item_rects.hpp"
#include "app/editor/widgets/scroll_keep.hpp"

namespace fraktal::editor {

namespace {
// Selects the tab named by `--tab` (or a command) once.
ImGuiTabItemFlags selectIf(const EditorState& s, const char* tab) {
    return s.panels.selectTab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
}

constexpr float kMinPanelWidth = 260.0f, kMinPanelHeight = 120.0f;

}  // namespace

bool sideColumnShows(const PanelVisibility& p, bool top) { return !p.collapsed && (top ? p.formula : p.sidebar); }

void beginSideColumnWindow(EditorState& s, const char* name, bool* open, bool top) {
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    Layout& l = s.layout;
    const float column = vp->WorkSize.y;
    const float maxWidth = std::max(vp->WorkSize.x * 0.45f, kMinPanelWidth);
    l.leftWidth = std::clamp(l.leftWidth, kMinPanelWidth, maxWidth);
    // Both shown: the Formula panel's height is the split (its lower edge resizes both).
    const bool shared = sideColumnShows(s.panels, true) && sideColumnShows(s.panels, false);
    const float maxSplit = std::max(column - kMinPanelHeight, kMinPanelHeight);
    if (shared) l.formulaHeight = std::clamp(l.formulaHeight, kMinPanelHeight, maxSplit);
    float y = vp->WorkPos.y, height = column;
    if (shared && top) height = l.formulaHeight;
    if (shared && !top) y += l.formulaHeight, height -= l.formulaHeight;
    const bool splitResizes = shared && top;
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x, y), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kMinPanelWidth, splitResizes ? kMinPanelHeight : height),
                                        ImVec2(maxWidth, splitResizes ? maxSplit : height));
    ImGui::SetNextWindowSize(ImVec2(l.leftWidth, height), ImGuiCond_Always);
    ImGui::Begin(name, open,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    // The column's panels lie behind every floating window, the Formula panel above the Scene
    // panel (drawn first, so sent back first). ImGui hands a press near a window's edge to the
    // front-most window whose rectangle, grown by the resize grip's reach, holds the pointer: with
    // the Scene panel in front (clicked last) it took every press on the split, and the Formula
    // panel's lower edge, the split's only grip, never moved.
    ImGui::BringWindowToDisplayBack(ImGui::GetCurrentWindow());
    // A drag of the window's edge this frame: the column and the split follow it from now on.
    if (ImGui::GetWindowWidth() != l.leftWidth) ImGui::MarkIniSettingsDirty();
    l.leftWidth = ImGui::GetWindowWidth();
    if (splitResizes) {
        if (ImGui::GetWindowHeight() != l.formulaHeight) ImGui::MarkIniSettingsDirty();
        l.formulaHeight = ImGui::GetWindowHeight();
    }
}

void keepWindowScroll() {
    const ImGuiWindow* w = ImGui::GetCurrentWindow();
    const float contentBottom = ImGui::GetCursorScreenPos().y;
    const float shownBottom = w->InnerRect.Max.y - w->WindowPadding.y;
    // Rounded up: ImGui rounds the content's height down, which would take the scroll back a pixel.
    const float pad = std::ceil(paddingKeepingScroll(contentBottom, shownBottom, w->Scroll.y));
    if (pad > 0.0f) ImGui::Dummy(ImVec2(0.0f, pad));
}

void noteWidgetRect(Layout& layout, const std::string& name) { noteItemRect(layout.widgetRects, name); }

void drawSidebar(EditorState& s) {
    if (!sideColumnShows(s.panels, false)) return;
    beginSideColumnWindow(s, "Scene", &s.panels.sidebar, false);
    // A 2D document shows its view rectangle instead of a camera, its colouring instead of shading.
    using Tab = std::pair<const char*, void (*)(EditorState&)>;
    const Tab scene[] = {{"Camera", drawCameraTab},
                         {"Render", drawRenderTab},
                         {"Shading", drawShadingTab},
                         {"Lights", drawLightsTab},
                         {"Presets", drawPresetsTab}};
    const Tab plane[] = {{"View", drawPlaneViewTab},
                         {"Render", drawRenderTab},
                         {"Colouring", drawPlaneColouringTab},
                         {"Presets", drawPresetsTab}};
    if (ImGui::BeginTabBar(s.doc.plane ? "plane_tabs" : "scene_tabs")) {
        for (const auto& [name, draw] : s.doc.plane ? std::span<const Tab>(plane) : std::span<const Tab>(scene)) {
            const bool shown = ImGui::BeginTabItem(name, nullptr, selectIf(s, name));
            noteWidgetRect(s.layout, std::string("tab:") + name);
            if (!shown) continue;
            s.layout.sceneTab = name;
            // The tab's body scrolls in its own region under the tab bar, which stays in place:
            // at 1280x800 the Scene panel is about 270 px tall, and most tabs run past its edge.
            ImGui::BeginChild("tab body", ImVec2(0.0f, 0.0f));
            draw(s);
            ImGui::EndChild();
            noteWidgetRect(s.layout, "child:Scene tab body");
            ImGui::EndTabItem();
        }
        ImGui::EndTabBar();
    }
    s.panels.selectTab.clear();
    ImGui::End();
}

}  // namespace fraktal::editor
