// Path prompts for Open / Save As (ImGui has no file dialog; the preset browser and drag and
// drop cover browsing) and the unsaved-changes question.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "app/editor/actions.hpp"
#include "app/editor/panels.hpp"

namespace fraktal::editor {

namespace {

bool pathPrompt(const char* id, const char* title, const char* button, bool& open, std::string& path) {
    if (open) {
        ImGui::OpenPopup(id);
        open = false;
    }
    bool accepted = false;
    ImGui::SetNextWindowSize(ImVec2(560, 0), ImGuiCond_Appearing);
    if (ImGui::BeginPopupModal(id, nullptr, ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
        ImGui::TextUnformatted(title);
        if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
        ImGui::SetNextItemWidth(540);
        const bool enter = ImGui::InputText("##path", &path, ImGuiInputTextFlags_EnterReturnsTrue);
        ImGui::TextDisabled("Tip: drop a preset or an exported EXR on the window to open it.");
        if ((ImGui::Button(button, ImVec2(120, 0)) || enter) && !path.empty()) {
            accepted = true;
            ImGui::CloseCurrentPopup();
        }
        ImGui::SameLine();
        if (ImGui::Button("Cancel", ImVec2(120, 0)) || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
            ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
    }
    return accepted;
}

}  // namespace

void drawFileDialogs(EditorState& s) {
    Dialogs& d = s.dialogs;
    if (pathPrompt("Open preset", "Preset (.json) or exported EXR to open:", "Open", d.openPath, d.pathInput))
        requestAction(s, {PendingKind::Open, d.pathInput});
    if (pathPrompt("Save preset as", "Save the preset to:", "Save", d.saveAs, d.pathInput)) {
        std::filesystem::path p(d.pathInput);
        if (p.extension() != ".json") p += ".json";
        if (saveDocumentAs(s, p) && d.pending.kind != PendingKind::None) runPending(s);
    }

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
