// Help > Shortcuts (F1): every keyboard shortcut and mouse gesture the editor knows.
#include <imgui.h>

#include "app/editor/panels/panels.hpp"

namespace fraktal::editor {

namespace {

struct Shortcut {
    const char* keys;
    const char* action;
};

// Keep in step with shortcuts.cpp and the menus.
constexpr Shortcut kShortcuts[] = {
    {"Ctrl+N / Ctrl+Shift+N", "New 3D / 2D document"},
    {"Ctrl+O", "Open a preset or an exported EXR (or drop one on the window)"},
    {"Ctrl+S / Ctrl+Shift+S", "Save / Save as"},
    {"F12", "Export still"},
    {"Ctrl+Z / Ctrl+Shift+Z, Ctrl+Y", "Undo / Redo (camera moves are not edits)"},
    {"Ctrl+Q", "Quit"},
    {"F1", "This list"},
    {"F2 / F3 / F4", "Formula panel / Scene panel / Stats overlay"},
    {"Ctrl+\\", "Hide / show the side panels (or the arrow in the menu bar)"},
    {"Ctrl+D, Delete", "Duplicate / remove the selected node"},
    {"Left drag", "Orbit (fly mode: look around); a click without a drag does nothing"},
    {"Ctrl+click", "Focus the lens on the surface under the cursor (depth of field on in the Lights tab)"},
    {"Right or middle drag", "Pan"},
    {"Wheel", "Zoom towards the target"},
    {"Space", "Play / pause the animation (cursor over the viewport or the timeline)"},
    {"Delete", "Remove the selected key (cursor over the timeline)"},
    {"Diamond before a value", "Key it at the current frame (filled: a key here; orange: edited since)"},
};

// Over the viewport, or after a click in it; never while typing.
constexpr Shortcut kCameraKeys[] = {
    {"F", "Frame the object"},
    {"V", "Orbit / fly mode"},
    {"W A S D, Q E (fly)", "Move; Shift: 4x"},
    {"Home", "Reset view"},
    {"1..4 / Ctrl+1..4", "Recall / store a view"},
};

// Two columns, the keys as wide as the widest, the actions wrapped at the window's edge.
template <size_t N>
void shortcutTable(const char* id, const Shortcut (&rows)[N]) {
    if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg)) return;
    ImGui::TableSetupColumn("keys", ImGuiTableColumnFlags_WidthFixed);
    ImGui::TableSetupColumn("action", ImGuiTableColumnFlags_WidthStretch);
    for (const Shortcut& k : rows) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(k.keys);
        ImGui::TableNextColumn();
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", k.action);
        ImGui::PopTextWrapPos();
    }
    ImGui::EndTable();
}

}  // namespace

void drawShortcutHelp(EditorState& s) {
    if (!s.panels.help) return;
    ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 40.0f, 0), ImGuiCond_FirstUseEver);
    if (ImGui::Begin("Shortcuts", &s.panels.help, ImGuiWindowFlags_NoSavedSettings)) {
        shortcutTable("shortcuts", kShortcuts);
        ImGui::Spacing();
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted("Camera keys (cursor over the viewport, or after a click in it; never while typing):");
        ImGui::PopTextWrapPos();
        shortcutTable("camera_keys", kCameraKeys);
    }
    ImGui::End();
}

}  // namespace fraktal::editor
