// The export dialog (F12): size presets or custom, the render mode (fast, or path traced with its
// samples and denoise, as the viewport shows it at rest), samples, EXR/PNG options; runs the still
// renderer in a child process (export_job.cpp) with a progress bar and a cancel button.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <string>

#include "app/editor/dialogs/export_widgets.hpp"
#include "app/editor/document/document.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/text_fit.hpp"

namespace fraktal::editor {

void drawExportDialog(EditorState& s) {
    ExportJob& job = s.exportJob;
    pollExport(job);
    if (!s.dialogs.exportStill) return;
    if (!beginExportDialog("Export still", &s.dialogs.exportStill)) return;
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
    drawExportProgress(job, exportStatusText(job), "", "rendering", s.now);
    drawExportLog(s, job, commandLine(exportCommand("fraktal", "<preset>", o)), "export:Command and log");
    endExportDialog();
}

}  // namespace fraktal::editor
