// The export dialog (F12): size presets or custom, the render mode (fast, or path traced with its
// samples and denoise, as the viewport shows it at rest), samples, EXR/PNG options; runs the still
// renderer in a child process (export_job.cpp) with a progress bar and a cancel button.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/editor/document/document.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/text_fit.hpp"

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
    // The dialog sizes itself to what it shows (the log opened, a longer status), its text
    // wrapped at a fixed width, so that nothing in it is cut or scrolls out of sight.
    const float width = ImGui::GetFontSize() * 36.0f;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (!ImGui::Begin("Export still", &s.dialogs.exportStill,
                      ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_AlwaysAutoResize)) {
        ImGui::End();
        return;
    }
    ImGui::PushItemWidth(width * 0.55f);
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ExportOptions& o = job.options;
    const bool running = exportActive(job);
    const bool plane = s.doc.plane.has_value();
    // The render mode the viewport shows, unless chosen here since the view's settings last changed.
    if (!running) followViewMode(o, s.doc.view.pathTraceAtRest, s.doc.view.pathSppCap);
    if (plane) o.pathTraced = false;  // 2D stills have one renderer
    bool edited = false;
    ImGui::BeginDisabled(running);
    if (ImGui::BeginCombo("Size", kExportSizes[o.sizeIndex].label)) {
        for (int i = 0; i < int(std::size(kExportSizes)); ++i)
            if (ImGui::Selectable(kExportSizes[i].label, i == o.sizeIndex)) {
                edited |= i != o.sizeIndex;
                o.sizeIndex = i;
            }
        ImGui::EndCombo();
    } else {
        checkComboFits("Size", kExportSizes[o.sizeIndex].label);
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
    edited |= dragClamped("Width", &o.width, 1, 4.0f, 16, 65536, "%d px");
    edited |= dragClamped("Height", &o.height, 1, 4.0f, 16, 65536, "%d px");
    ImGui::EndDisabled();
    if (!plane) {
        int mode = o.pathTraced ? 1 : 0;
        const char* modes[] = {"Fast", "Path traced"};
        if (ImGui::Combo("Render mode", &mode, modes, IM_ARRAYSIZE(modes))) {
            edited |= o.pathTraced != (mode == 1);
            o.pathTraced = mode == 1;
        }
        checkComboFits("Render mode", modes[mode]);
        noteWidgetRect(s.layout, "export:Render mode");
        helpMarker(
            "Fast: the renderer of the moving viewport. Path traced: the scene's lights, environment map and lens, "
            "as the viewport shows it at rest in its path-traced mode. It starts as the Render tab's render "
            "mode.");
    }
    edited |= dragClamped("Samples per pixel", o.pathTraced ? &o.pathSpp : &o.spp, 1, 0.25f, 1, 4096, "%d");
    noteWidgetRect(s.layout, "export:Samples per pixel");
    if (o.pathTraced) {
        edited |= ImGui::Checkbox("Denoise", &o.denoise);
        noteWidgetRect(s.layout, "export:Denoise");
        helpMarker(
            "A joint bilateral filter guided by the albedo, normal and depth passes: it smooths the lighting, "
            "not the texture.");
    }
    if (!plane)
        if (const std::string lights = exportLightsText(s.doc.preset.lighting, o.pathTraced); !lights.empty()) {
            if (o.pathTraced)
                ImGui::TextDisabled("%s", lights.c_str());
            else
                ImGui::TextColored(ImVec4(0.95f, 0.75f, 0.35f, 1), "%s", lights.c_str());
        }
    sectionHeader("Output");
    edited |= ImGui::InputText("File (no extension)", &o.output);
    noteWidgetRect(s.layout, "export:File");
    ImGui::TextDisabled(
        "An OpenEXR file is always written: the full range of light, with depth, normals and "
        "the other passes, and the scene itself, so that the file opens again in the editor.");
    edited |= ImGui::Checkbox("Half float", &o.halfFloat);
    ImGui::SameLine();
    edited |= ImGui::Checkbox("PNG preview", &o.pngPreview);
    helpMarker("With the Render tab's view and exposure, as the viewport shows it.");
    ImGui::EndDisabled();
    // A finished job's Done, Failed or Cancelled speaks of its own files, not of the options now.
    if (edited) exportOptionsEdited(job);
    ImGui::TextDisabled("%.1f megapixels, %.1f MB as half EXR", o.width * double(o.height) / 1e6,
                        o.width * double(o.height) * 8.0 / 1e6);

    ImGui::Spacing();
    if (!running) {
        if (ImGui::Button("Render", ImVec2(120, 0))) startExport(job, exportPresetText(s.doc, s.file.path), s.now);
        noteWidgetRect(s.layout, "export:Render");
    } else {
        ImGui::BeginDisabled(job.status == ExportStatus::Cancelling);
        if (ImGui::Button("Cancel", ImVec2(120, 0))) cancelExport(job);
        ImGui::EndDisabled();
    }
    ImGui::SameLine();
    const double elapsed = running ? s.now - job.startedAt : 0.0;
    const std::string status = exportStatusText(job);
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
    // The command line and the renderer's output, for a bug report or a render farm: wrapped,
    // in a region as tall as the log up to half the window, then scrolled to its newest line.
    const bool logOpen = ImGui::CollapsingHeader("Command and log");
    noteWidgetRect(s.layout, "export:Command and log");
    if (logOpen) {
        ImGui::TextDisabled("%s", joined(exportCommand("fraktal", "<preset>", o)).c_str());
        const std::string log = job.log.empty() ? std::string("(nothing yet)") : job.log;
        const float textHeight = ImGui::CalcTextSize(log.c_str(), nullptr, false, width).y;
        const float height = std::min(textHeight + ImGui::GetStyle().WindowPadding.y * 2.0f,
                                      ImGui::GetMainViewport()->WorkSize.y * 0.5f);
        ImGui::BeginChild("log", ImVec2(width, height), true);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(log.c_str());
        ImGui::PopTextWrapPos();
        if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY()) ImGui::SetScrollHereY(1.0f);
        ImGui::EndChild();
    }
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
    ImGui::End();
}

}  // namespace fraktal::editor
