// The file browser for Open / Save As (ImGui has none): places (shipped presets, the user's
// presets, home, recent folders and files), the folder's entries with folders first, a path
// field, a filter; Enter opens, Escape cancels, Save asks before replacing a file. And the
// unsaved-changes question.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "app/editor/document/file_browser.hpp"
#include "app/editor/document/preset_files.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/widgets/node_list_widgets.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

namespace {

void goTo(FileBrowser& b, const fs::path& folder) {
    b.folder = folder.lexically_normal();
    if (b.folder.filename().empty() && b.folder.has_relative_path()) b.folder = b.folder.parent_path();  // "a/b/"
    b.listed = false;
    b.error.clear();
}

// Where the browser starts: the document's folder, else the last folder used, else `fallback`.
void startBrowser(EditorState& s, bool saving, const fs::path& fallback) {
    FileBrowser& b = s.dialogs.browser;
    b.saving = saving;
    b.replace.clear();
    // Open and Save list presets; only the environment map's browser lists every EXR.
    if (b.filter == BrowserFilter::EnvironmentMaps) b.filter = BrowserFilter::PresetsAndExrs;
    const std::vector<fs::path> recent = recentFolders(s.file.recent);
    goTo(b, !s.file.path.empty() ? fs::absolute(s.file.path).parent_path()
            : !recent.empty()    ? recent.front()
                                 : fallback);
    b.name = saving && !s.file.path.empty() ? s.file.path.filename().string() : "";
}

bool place(FileBrowser& b, const char* label, const fs::path& folder) {
    if (!ImGui::Selectable(label, b.folder == folder.lexically_normal())) return false;
    goTo(b, folder);
    return true;
}

// The places column: a recent file picks its folder and name.
void places(FileBrowser& b, const std::vector<std::string>& recent) {
    const fs::path presets = fs::path(FRAKTAL_SOURCE_DIR) / "presets";
    place(b, "Shipped presets", presets);
    place(b, "Shipped 2D presets", presets / "2d");
    place(b, "My presets", userPresetFolder());
    if (const char* home = std::getenv("HOME"); home && *home) place(b, "Home", home);
    sectionHeader("Recent folders");
    for (const fs::path& f : recentFolders(recent)) {
        ImGui::PushID(f.c_str());
        place(b, f.filename().empty() ? f.c_str() : f.filename().c_str(), f);
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", f.c_str());
        ImGui::PopID();
    }
    sectionHeader("Recent files");
    for (const std::string& r : recent) {
        const fs::path f(r);
        ImGui::PushID(r.c_str());
        if (ImGui::Selectable(f.filename().c_str(), false)) {
            goTo(b, f.parent_path());
            b.name = f.filename().string();
        }
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", r.c_str());
        ImGui::PopID();
    }
}

// The folder's entries; a double-click opens a folder or chooses a file. True: choose b.name.
bool entries(FileBrowser& b) {
    bool choose = false;
    fs::path enter;
    for (const BrowserEntry& e : b.entries) {
        const std::string label = e.folder ? e.name + "/" : e.name;
        if (!e.usable) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
        if (ImGui::Selectable(label.c_str(), !e.folder && e.name == b.name, ImGuiSelectableFlags_AllowDoubleClick)) {
            const bool twice = ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left);
            if (e.folder) {
                if (twice) enter = b.folder / e.name;
            } else {
                b.name = e.name;
                choose = twice && e.usable;
            }
        }
        if (!e.usable) {
            ImGui::PopStyleColor();
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("Cannot be opened: %s", e.note.c_str());
        }
    }
    if (!b.error.empty()) ImGui::TextColored(kErrorColor, "%s", b.error.c_str());
    if (!enter.empty()) goTo(b, enter);
    return choose;
}

// The path the field names: a folder to go into, or the file to open or save.
fs::path fieldPath(const FileBrowser& b) {
    fs::path p(b.name);
    if (!b.name.empty() && b.name[0] == '~')
        if (const char* home = std::getenv("HOME")) p = fs::path(home) / b.name.substr(b.name.size() > 1 ? 2 : 1);
    return p.is_absolute() ? p : b.folder / p;
}

// The browser as a modal popup; returns the chosen file once (Save: after any replace question).
// Enter and Escape come from the window's key events (EditorState::keyPresses): ImGui 1.86 polls
// key state once a frame and misses a tap that starts and ends between two frames.
bool tapped(const std::vector<KeyPress>& presses, int key, int alsoKey = -1) {
    return std::any_of(presses.begin(), presses.end(),
                       [&](const KeyPress& p) { return p.key == key || p.key == alsoKey; });
}

std::optional<fs::path> fileBrowser(FileBrowser& b, const char* id, const std::vector<std::string>& recent,
                                    const std::vector<KeyPress>& keys) {
    std::optional<fs::path> chosen;
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    ImGui::SetNextWindowSize(ImVec2(std::min(820.0f, display.x - 40), std::min(520.0f, display.y - 60)),
                             ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.5f), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_NoSavedSettings)) return chosen;
    b.shown = true;
    if (!b.listed) {
        b.entries = listFolder(b.folder, b.filter, b.error);
        b.listed = true;
    }
    if (ImGui::Button("Up") && b.folder.has_parent_path()) goTo(b, b.folder.parent_path());
    ImGui::SameLine();
    ImGui::TextUnformatted(b.folder.c_str());
    const float footer = ImGui::GetFrameHeightWithSpacing() * 2 + ImGui::GetStyle().ItemSpacing.y;
    ImGui::BeginChild("places", ImVec2(210, -footer), true);
    places(b, recent);
    ImGui::EndChild();
    ImGui::SameLine();
    ImGui::BeginChild("entries", ImVec2(0, -footer), true);
    bool accept = entries(b);
    ImGui::EndChild();

    if (ImGui::IsWindowAppearing() || b.focusField) ImGui::SetKeyboardFocusHere();
    b.focusField = false;
    ImGui::SetNextItemWidth(-220);
    // A field per folder: going into a folder starts an empty one (an active field keeps its text).
    ImGui::PushID(b.folder.c_str());
    ImGui::InputTextWithHint("##path", b.saving ? "file name or path" : "file name, path or folder", &b.name);
    b.fieldActive = ImGui::IsItemActive();
    ImGui::PopID();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1);
    int filter = int(b.filter);
    if (b.filter == BrowserFilter::EnvironmentMaps)
        ImGui::TextDisabled("%s", kBrowserFilterNames[filter]);
    else if (ImGui::Combo("##filter", &filter, kBrowserFilterNames, kOpenFilters)) {
        b.filter = BrowserFilter(filter);
        b.listed = false;
    }
    accept |= ImGui::Button(b.saving ? "Save" : "Open", ImVec2(120, 0));
    ImGui::SameLine();
    const bool replacing = !b.replace.empty();
    // Enter chooses, Escape cancels, unless the replace question has the keys.
    if (!replacing && tapped(keys, GLFW_KEY_ENTER, GLFW_KEY_KP_ENTER)) accept = true;
    if (ImGui::Button("Cancel", ImVec2(120, 0)) || (!replacing && tapped(keys, GLFW_KEY_ESCAPE)))
        ImGui::CloseCurrentPopup();

    if (accept && !b.name.empty()) {
        fs::path p = fieldPath(b);
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            goTo(b, p);
            b.name.clear();
            b.focusField = true;  // type on: the next name
        } else if (b.saving) {
            if (p.extension() != ".json") p += ".json";
            if (fs::exists(p, ec))
                b.replace = p;
            else
                chosen = p;
        } else if (!fs::is_regular_file(p, ec)) {
            b.error = "No such file: " + p.string();
        } else {
            chosen = p;
        }
    }
    if (!b.replace.empty()) ImGui::OpenPopup("Replace file?");
    if (ImGui::BeginPopupModal("Replace file?", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("%s already exists. Replace it?", b.replace.filename().c_str());
        ImGui::TextDisabled("The previous version is kept as %s.bak.", b.replace.filename().c_str());
        if (ImGui::Button("Replace", ImVec2(110, 0))) {
            chosen = b.replace;
            b.replace.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(110, 0)) || (replacing && tapped(keys, GLFW_KEY_ESCAPE))) {
            b.replace.clear();
            ImGui::CloseCurrentPopup();
        }
        ImGui::EndPopup();
    }
    if (chosen) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return chosen;
}

}  // namespace

void drawFileDialogs(EditorState& s) {
    Dialogs& d = s.dialogs;
    d.browser.shown = false;
    d.browser.fieldActive = false;
    if (d.openPath) {
        startBrowser(s, false, fs::path(FRAKTAL_SOURCE_DIR) / "presets");
        ImGui::OpenPopup("Open");
        d.openPath = false;
    }
    if (d.saveAs) {
        startBrowser(s, true, userPresetFolder());
        if (!d.pathInput.empty()) {
            const fs::path start = fs::absolute(d.pathInput);
            goTo(d.browser, start.parent_path());
            d.browser.name = start.filename().string();
        }
        ImGui::OpenPopup("Save as");
        d.saveAs = false;
    }
    if (d.environmentMap) {
        startBrowser(s, false, fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "env");
        d.browser.filter = BrowserFilter::EnvironmentMaps;
        d.browser.listed = false;
        ImGui::OpenPopup("Environment map");
        d.environmentMap = false;
    }
    if (const auto file = fileBrowser(d.browser, "Environment map", s.file.recent, s.keyPresses))
        chooseEnvironmentMap(s, *file);
    if (const auto file = fileBrowser(d.browser, "Open", s.file.recent, s.keyPresses))
        requestAction(s, {PendingKind::Open, *file});
    if (const auto file = fileBrowser(d.browser, "Save as", s.file.recent, s.keyPresses))
        if (saveDocumentAs(s, *file) && d.pending.kind != PendingKind::None) runPending(s);

    if (d.unsaved) {
        ImGui::OpenPopup("Unsaved changes");
        d.unsaved = false;
    }
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::Text("Save the changes to %s?",
                    s.file.path.empty() ? "this untitled preset" : s.file.path.filename().string().c_str());
        ImGui::TextDisabled("Your changes are lost if you don't save them.");
        ImGui::Spacing();
        if (ImGui::Button("Save", ImVec2(110, 0))) {
            ImGui::CloseCurrentPopup();
            if (saveDocument(s)) runPending(s);
            // else Save As opens; the pending action runs after it.
        }
        ImGui::SameLine();
        if (ImGui::Button("Don't save", ImVec2(110, 0))) {
            ImGui::CloseCurrentPopup();
            runPending(s);
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(110, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) {
            ImGui::CloseCurrentPopup();
            d.pending = {};
        }
        ImGui::EndPopup();
    }
}

}  // namespace fraktal::editor
