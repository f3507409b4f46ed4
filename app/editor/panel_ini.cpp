#include "app/editor/panel_ini.hpp"

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
    auto* p = static_cast<PanelVisibility*>(entry);
    int v = 0;
    if (std::sscanf(line, "Formula=%d", &v) == 1) p->formula = v != 0;
    else if (std::sscanf(line, "Scene=%d", &v) == 1) p->sidebar = v != 0;
    else if (std::sscanf(line, "Stats=%d", &v) == 1) p->stats = v != 0;
}

void writeAll(ImGuiContext*, ImGuiSettingsHandler* h, ImGuiTextBuffer* out) {
    const auto* p = static_cast<const PanelVisibility*>(h->UserData);
    out->appendf("[%s][Panels]\nFormula=%d\nScene=%d\nStats=%d\n\n", h->TypeName, int(p->formula), int(p->sidebar),
                 int(p->stats));
}

}  // namespace

void registerPanelIniHandler(PanelVisibility& panels) {
    ImGuiSettingsHandler h;
    h.TypeName = "Fraktal";
    h.TypeHash = ImHashStr("Fraktal");
    h.ReadOpenFn = readOpen;
    h.ReadLineFn = readLine;
    h.WriteAllFn = writeAll;
    h.UserData = &panels;
    ImGui::GetCurrentContext()->SettingsHandlers.push_back(h);
}

}  // namespace fraktal::editor
