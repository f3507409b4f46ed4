// The Help menu's windows: Shortcuts (F1), every keyboard shortcut and mouse gesture the editor
// knows, and Tour, the artist's tour of the editor (app/editor/TOUR.md) as text.
#include <imgui.h>

#include <fstream>
#include <sstream>
#include <string>
#include <string_view>

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

// The tour's Markdown as plain paragraphs: headings stand out, images are left out, and the marks
// of emphasis and code are dropped.
void drawTourText(const std::string& markdown) {
    std::istringstream lines(markdown);
    std::string line, paragraph;
    const auto flush = [&paragraph] {
        if (paragraph.empty()) return;
        ImGui::TextUnformatted(paragraph.c_str());
        ImGui::Spacing();
        paragraph.clear();
    };
    while (std::getline(lines, line)) {
        if (line.starts_with("![")) continue;
        std::string plain;
        for (char c : line)
            if (c != '*' && c != '`') plain += c;
        if (plain.starts_with("#")) {
            flush();
            const size_t text = plain.find_first_not_of("# ");
            ImGui::Spacing();
            ImGui::TextColored(ImVec4(0.95f, 0.8f, 0.5f, 1), "%s",
                               plain.substr(text == std::string::npos ? 0 : text).c_str());
            ImGui::Separator();
        } else if (plain.find_first_not_of(' ') == std::string::npos) {
            flush();
        } else {
            paragraph += (paragraph.empty() ? "" : " ") + plain;
        }
    }
    flush();
}

void drawTour(EditorState& s) {
    if (!s.panels.tour) return;
    if (s.panels.tourText.empty()) {
        std::ifstream in(std::string(FRAKTAL_SOURCE_DIR) + "/app/editor/TOUR.md");
        std::ostringstream text;
        text << in.rdbuf();
        s.panels.tourText = in ? text.str() : "The tour (app/editor/TOUR.md) could not be read.";
    }
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 40.0f, vp->WorkSize.y * 0.8f), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(vp->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Tour", &s.panels.tour, ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::PushTextWrapPos(0.0f);
        drawTourText(s.panels.tourText);
        ImGui::PopTextWrapPos();
    }
    ImGui::End();
}

}  // namespace

void drawShortcutHelp(EditorState& s) {
    drawTour(s);
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
