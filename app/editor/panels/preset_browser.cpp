// The presets tab: recent files, then a thumbnail grid of the shipped presets/ folder and the
// user's own folder. Thumbnails are rendered by thumbnails.cpp, a few milliseconds a frame.
#include <imgui.h>

#include <algorithm>
#include <filesystem>

#include "app/editor/document/preset_files.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/widgets/param_widgets.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

namespace {

void scan(PresetBrowser& b) {
    b.entries.clear();
    for (const fs::path& folder : b.folders) {
        std::error_code ec;
        std::vector<fs::path> files;
        for (const auto& e : fs::directory_iterator(folder, ec))
            if (e.is_regular_file() && e.path().extension() == ".json") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        for (const fs::path& f : files) b.entries.push_back(Thumbnail{f, f.stem().string()});
    }
    b.scanned = true;
}

// The thumbnails' region where it shows (inside its child window, before any thumbnail).
void noteThumbnails(Layout& layout) {
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    layout.widgetRects["child:Presets thumbnails"] = {at.x, at.y, size.x, size.y};
}

}  // namespace

void drawPresetsTab(EditorState& s) {
    PresetBrowser& b = s.browser;
    b.visible = true;
    if (!b.scanned) scan(b);

    sectionHeader("Recent files");
    if (s.file.recent.empty()) ImGui::TextDisabled("None yet.");
    for (const std::string& r : s.file.recent) {
        if (ImGui::Selectable(fs::path(r).filename().string().c_str())) requestAction(s, {PendingKind::Open, r});
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.c_str());
    }

    sectionHeader("Browse");
    if (ImGui::SmallButton("Rescan")) scan(b);
    ImGui::SameLine();
    ImGui::TextDisabled("%zu presets", b.entries.size());
    ImGui::PushTextWrapPos(0.0f);
    for (const fs::path& folder : b.folders) ImGui::TextDisabled("%s", folder.string().c_str());
    ImGui::PopTextWrapPos();

    // The thumbnails scroll in their own region under the tab bar, which stays in place.
    ImGui::BeginChild("thumbnails", ImVec2(0, 0));
    noteThumbnails(s.layout);
    const float thumbW = 136.0f, thumbH = 85.0f;
    const int columns =
        std::max(1, int(ImGui::GetContentRegionAvail().x / (thumbW + ImGui::GetStyle().ItemSpacing.x + 8)));
    int column = 0;
    for (size_t i = 0; i < b.entries.size(); ++i) {
        Thumbnail& t = b.entries[i];
        ImGui::PushID(int(i));
        ImGui::BeginGroup();
        bool clicked = false;
        if (t.texture) {
            // Copies of the viewports' display textures: top row first, as the viewport shows them.
            clicked = ImGui::ImageButton(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(t.texture)),
                                         ImVec2(thumbW, thumbH), ImVec2(0, 0), ImVec2(1, 1));
        } else {
            clicked = ImGui::Button(
                t.failed ? "(cannot render)" : "rendering...",
                ImVec2(thumbW + ImGui::GetStyle().FramePadding.x * 2, thumbH + ImGui::GetStyle().FramePadding.y * 2));
        }
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + thumbW);
        ImGui::TextUnformatted(t.name.c_str());
        ImGui::PopTextWrapPos();
        ImGui::EndGroup();
        if (i == 0) noteWidgetRect(s.layout, "thumbnail:1");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\nClick to open", t.file.string().c_str());
        if (clicked) requestAction(s, {PendingKind::Open, t.file});
        ImGui::PopID();
        if (++column < columns)
            ImGui::SameLine();
        else
            column = 0;
    }
    ImGui::EndChild();
}

}  // namespace fraktal::editor
