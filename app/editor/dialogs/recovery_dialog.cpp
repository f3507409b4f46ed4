// The restore prompt after a crash (autosave.hpp): shown once at start when the previous session
// left a recovery file without ending cleanly.
#include <imgui.h>

#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"

namespace fraktal::editor {

void drawRecoveryDialog(EditorState& s) {
    if (!s.autosave.offer) return;
    constexpr const char* kId = "Restore unsaved work?";
    if (!ImGui::IsPopupOpen(kId)) ImGui::OpenPopup(kId);
    if (!ImGui::BeginPopupModal(kId, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
    const std::filesystem::path& original = s.autosave.offer->originalFile;
    ImGui::TextUnformatted("fraktal did not shut down cleanly last time.");
    ImGui::Text("Restore the document autosaved from %s?",
                original.empty() ? "an untitled preset" : original.string().c_str());
    ImGui::TextDisabled("It opens with unsaved changes; Discard deletes the recovery file.");
    ImGui::Spacing();
    if (ImGui::Button("Restore", ImVec2(110, 0))) {
        ImGui::CloseCurrentPopup();
        if (std::optional<RecoveryOffer> offer = answerRecovery(s.autosave, true))
            restoreDocument(s, std::move(*offer));
    }
    ImGui::SameLine();
    if (ImGui::Button("Discard", ImVec2(110, 0))) {
        ImGui::CloseCurrentPopup();
        answerRecovery(s.autosave, false);
    }
    ImGui::EndPopup();
}

}  // namespace fraktal::editor
