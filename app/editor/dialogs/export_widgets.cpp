#include "app/editor/dialogs/export_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>

namespace fraktal::editor {

float exportDialogWidth() { return ImGui::GetFontSize() * 36.0f; }

bool beginExportDialog(const char* title, bool* open) {
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin(title, open, ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return false;
    }
    ImGui::PushItemWidth(exportDialogWidth() * 0.55f);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + exportDialogWidth());
    return true;
}

void endExportDialog() {
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
    ImGui::End();
}

void drawExportProgress(const ExportProcess& job, const std::string& status, const std::string& stage, const char* verb,
                        double now) {
    switch (job.status) {
        case ExportStatus::Running:
            if (job.progress >= 0.0) {
                const std::string text =
                    stage.empty() ? std::string() : stage + " " + std::to_string(int(job.progress * 100.0)) + "%";
                ImGui::ProgressBar(float(job.progress), ImVec2(-1, 0), text.empty() ? nullptr : text.c_str());
            } else {
                // The child has not reported a percentage: show time, not a fake fraction.
                const double elapsed = now - job.startedAt;
                const std::string text = std::string(verb) + ", " + std::to_string(int(elapsed)) + " s";
                ImGui::ProgressBar(float(std::fmod(elapsed, 2.0) / 2.0), ImVec2(-1, 0), text.c_str());
            }
            break;
        case ExportStatus::Done:
            if (exportOutputsExist(job))
                ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1), "%s", status.c_str());
            else
                ImGui::TextDisabled("%s", status.c_str());
            break;
        case ExportStatus::Failed: ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "%s", status.c_str()); break;
        case ExportStatus::Cancelling:
        case ExportStatus::Cancelled:
        case ExportStatus::Idle: ImGui::TextDisabled("%s", status.c_str()); break;
    }
}

void drawExportLog(EditorState& s, const ExportProcess& job, const std::string& command, const std::string& rectName) {
    const float width = exportDialogWidth();
    // For a bug report or a render farm: the command runs as shown, with the document's preset.
    const bool logOpen = ImGui::CollapsingHeader("Command and log");
    noteWidgetRect(s.layout, rectName);
    if (!logOpen) return;
    ImGui::TextDisabled("%s", command.c_str());
    const std::string log = job.log.empty() ? std::string("(nothing yet)") : job.log;
    const float textHeight = ImGui::CalcTextSize(log.c_str(), nullptr, false, width).y;
    const float height =
        std::min(textHeight + ImGui::GetStyle().WindowPadding.y * 2.0f, ImGui::GetMainViewport()->WorkSize.y * 0.5f);
    ImGui::BeginChild("log", ImVec2(width, height), true);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(log.c_str());
    ImGui::PopTextWrapPos();
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
}

}  // namespace fraktal::editor
