// The export dialog (F12): size presets or custom, samples, EXR/PNG options; runs the still
// renderer in a child process (export_job.cpp) with a progress bar and a cancel button.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cmath>
#include <string>

#include "app/editor/document/document.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/widgets/param_widgets.hpp"

namespace fraktal::editor {

namespace {

std::string joined(const std::vector<std::string>& args) {
    std::string out;
    for (const std::string& a : args) out += (out.empty() ? "" : " ") + a;
    return out;
}

}  // namespace

void drawExportDialog(EditorState& s) {
    ExportJob& job = s.exportJob;
    pollExport(job);
    if (!s.dialogs.exportStill) return;
    ImGui::SetNextWindowSize(ImVec2(520, 0), ImGuiCond_Appearing);
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("Export still", &s.dialogs.exportStill, ImGuiWindowFlags_NoCollapse)) {
        ImGui::End();
        return;
    }
    ExportOptions& o = job.options;
    const bool running = exportActive(job);
    ImGui::BeginDisabled(running);
    if (ImGui::BeginCombo("Size", kExportSizes[o.sizeIndex].label)) {
        for (int i = 0; i < int(std::size(kExportSizes)); ++i)
            if (ImGui::Selectable(kExportSizes[i].label, i == o.sizeIndex)) o.sizeIndex = i;
        ImGui::EndCombo();
    }
    const ExportSize& size = kExportSizes[o.sizeIndex];
    if (size.width > 0) {
        o.width = size.width;
        o.height = size.height;
    } else if (size.width == 0) {
        o.width = int(s.layout.viewportW);
        o.height = int(s.layout.viewportH);
    }
    ImGui::BeginDisabled(size.width >= 0);
    ImGui::DragInt("Width", &o.width, 4.0f, 16, 65536, "%d px", ImGuiSliderFlags_AlwaysClamp);
    ImGui::DragInt("Height", &o.height, 4.0f, 16, 65536, "%d px", ImGuiSliderFlags_AlwaysClamp);
    ImGui::EndDisabled();
    ImGui::DragInt("Samples per pixel", &o.spp, 0.25f, 1, 4096, "%d", ImGuiSliderFlags_AlwaysClamp);
    sectionHeader("Output");
    ImGui::InputText("File (no extension)", &o.output);
    ImGui::TextDisabled("OpenEXR (scene-linear, AOVs, the preset embedded) is always written.");
    ImGui::Checkbox("Half float", &o.halfFloat);
    ImGui::SameLine();
    ImGui::Checkbox("PNG preview", &o.pngPreview);
    helpMarker("Through the Render tab's OCIO view and exposure, as the viewport shows it.");
    ImGui::EndDisabled();
    ImGui::TextDisabled("%.1f megapixels, %.1f MB as half EXR", o.width * double(o.height) / 1e6,
                        o.width * double(o.height) * 8.0 / 1e6);

    ImGui::Spacing();
    if (!running) {
        if (ImGui::Button("Render", ImVec2(120, 0))) startExport(job, documentFileText(s.doc), s.now);
    } else {
        ImGui::BeginDisabled(job.status == ExportStatus::Cancelling);
        if (ImGui::Button("Cancel", ImVec2(120, 0))) cancelExport(job);
        ImGui::EndDisabled();
    }
    ImGui::SameLine();
    const double elapsed = running ? s.now - job.startedAt : 0.0;
    switch (job.status) {
        case ExportStatus::Running:
            if (job.progress >= 0.0) {
                ImGui::ProgressBar(float(job.progress), ImVec2(-1, 0));
            } else {
                // The renderer has not reported a percentage: show time, not a fake fraction.
                const std::string text = "rendering, " + std::to_string(int(elapsed)) + " s";
                ImGui::ProgressBar(float(std::fmod(elapsed, 2.0) / 2.0), ImVec2(-1, 0), text.c_str());
            }
            break;
        case ExportStatus::Cancelling: ImGui::TextDisabled("Cancelling after the current tile..."); break;
        case ExportStatus::Done:
            ImGui::TextColored(ImVec4(0.5f, 0.9f, 0.5f, 1), "Done: %s.exr%s", o.output.c_str(),
                               o.pngPreview ? " and .png" : "");
            break;
        case ExportStatus::Failed: ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "Failed (see log)."); break;
        case ExportStatus::Cancelled: ImGui::TextDisabled("Cancelled."); break;
        case ExportStatus::Idle: ImGui::TextDisabled("The UI stays usable while it renders."); break;
    }
    if (ImGui::CollapsingHeader("Command and log")) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled("%s", joined(exportCommand("fraktal", "<preset>", o)).c_str());
        ImGui::PopTextWrapPos();
        ImGui::InputTextMultiline("##log", &job.log, ImVec2(-1, 140), ImGuiInputTextFlags_ReadOnly);
    }
    ImGui::End();
}

}  // namespace fraktal::editor
