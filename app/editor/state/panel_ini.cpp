#include "app/editor/state/panel_ini.hpp"

#include <imgui.h>
#include <imgui_internal.h>

#include <cstdio>
#include <cstring>

namespace fraktal::editor {

namespace {

void* readOpen(ImGuiContext*, ImGuiSettingsHandler* h, const char* name) {
    return std::strcmp(name, "Panels") == 0 ? h->UserData : nullptr;
}

void readLine(ImGuiContext*, ImGuiSettingsHandler*, void* entry, const char* line) {
    auto& s = *static_cast<EditorState*>(entry);
    PanelVisibility& p = s.panels;
    WindowPlacement& w = s.window;
    int v = 0, x = 0, y = 0, width = 0, height = 0;
    float f = 0.0f;
    if (std::sscanf(line, "Formula=%d", &v) == 1)
        p.formula = v != 0;
    else if (std::sscanf(line, "Scene=%d", &v) == 1)
        p.sidebar = v != 0;
    else if (std::sscanf(line, "Stats=%d", &v) == 1)
        p.stats = v != 0;
    else if (std::sscanf(line, "Collapsed=%d", &v) == 1)
        p.collapsed = v != 0;
    else if (std::sscanf(line, "ColumnWidth=%f", &f) == 1 && f > 0.0f)
        s.layout.leftWidth = f;
    else if (std::sscanf(line, "FormulaHeight=%f", &f) == 1 && f > 0.0f)
        s.layout.formulaHeight = f;
    else if (std::sscanf(line, "WindowSize=%d,%d", &width, &height) == 2 && width > 0 && height > 0)
        w.width = width, w.height = height;
    else if (std::sscanf(line, "WindowPos=%d,%d", &x, &y) == 2)
        w.x = x, w.y = y, w.hasPosition = true;
}

void writeAll(ImGuiContext*, ImGuiSettingsHandler* h, ImGuiTextBuffer* out) {
    const auto& s = *static_cast<const EditorState*>(h->UserData);
    const PanelVisibility& p = s.panels;
    out->appendf("[%s][Panels]\nFormula=%d\nScene=%d\nStats=%d\nCollapsed=%d\nColumnWidth=%.0f\nFormulaHeight=%.0f\n",
                 h->TypeName, int(p.formula), int(p.sidebar), int(p.stats), int(p.collapsed), s.layout.leftWidth,
                 s.layout.formulaHeight);
    if (s.window.width > 0) out->appendf("WindowSize=%d,%d\n", s.window.width, s.window.height);
    if (s.window.hasPosition) out->appendf("WindowPos=%d,%d\n", s.window.x, s.window.y);
    out->append("\n");
}

}  // namespace

void registerPanelIniHandler(EditorState& s) {
    ImGuiSettingsHandler h;
    h.TypeName = "Fraktal";
    h.TypeHash = ImHashStr("Fraktal");
    h.ReadOpenFn = readOpen;
    h.ReadLineFn = readLine;
    h.WriteAllFn = writeAll;
    h.UserData = &s;
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(h);
}

}  // namespace fraktal::editor
