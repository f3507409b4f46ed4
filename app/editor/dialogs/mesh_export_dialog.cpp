// The mesh export dialog (File > Export mesh...): the format (the file's extension), resolution
// with the voxel size it gives, simplify, print size, cavities, minimum thickness and vertex
// colours; runs `fraktal mesh` on the document as
// the viewport shows it in a child process (document/mesh_export_job.cpp) with a progress bar and
// a cancel button.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <iterator>
#include <string>

#include "app/editor/dialogs/export_widgets.hpp"
#include "app/editor/document/document.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/text_fit.hpp"

namespace fraktal::editor {

namespace {

struct MeshFormatChoice {
    const char* format;  // one of kMeshFormats
    const char* label;
    const char* help;
};

constexpr MeshFormatChoice kMeshFormatChoices[] = {
    {".ply", "PLY (.ply)", "Binary PLY: slicers and Blender, MeshLab."},
    {".glb", "glTF binary (.glb)", "glTF 2, one binary file: web viewers, Blender, game engines."},
    {".obj", "OBJ (.obj)", "Wavefront OBJ, text, without a material file: opens almost anywhere."},
    {".stl", "STL (.stl)", "Binary STL: what every slicer takes for printing."},
    {".vdb", "OpenVDB level set (.vdb)",
     "The signed distance as a sparse narrow-band level set (OpenVDB): Houdini, Blender's volume "
     "tools. In the preset's units: no print size."},
};
static_assert(std::size(kMeshFormatChoices) == std::size(kMeshFormats));

const MeshFormatChoice* choiceOf(const std::string& format) {
    for (const MeshFormatChoice& c : kMeshFormatChoices)
        if (format == c.format) return &c;
    return nullptr;
}

// The combo: the output's format; a choice replaces the output's extension.
bool formatCombo(MeshExportOptions& o) {
    const MeshFormatChoice* current = choiceOf(meshFormat(o.output));
    const char* shown = current ? current->label : "(unknown extension)";
    bool edited = false;
    if (ImGui::BeginCombo("Format", shown)) {
        for (const MeshFormatChoice& c : kMeshFormatChoices) {
            if (ImGui::Selectable(c.label, &c == current) && &c != current) {
                o.output = withMeshFormat(o.output, c.format);
                edited = true;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c.help);
        }
        ImGui::EndCombo();
    } else {
        checkComboFits("Format", shown);
    }
    return edited;
}

}  // namespace

void drawMeshExportDialog(EditorState& s) {
    MeshExportJob& job = s.meshExportJob;
    pollExport(job);
    if (!s.dialogs.exportMesh || !beginExportDialog("Export mesh", &s.dialogs.exportMesh)) return;
    const ImVec2 windowPos = ImGui::GetWindowPos(), windowSize = ImGui::GetWindowSize();
    s.layout.widgetRects["meshExport:window"] = {windowPos.x, windowPos.y, windowSize.x, windowSize.y};
    MeshExportOptions& o = job.options;
    const bool running = exportActive(job);
    // A document made 2D while the dialog is open (File > New 2D) has nothing to mesh.
    const bool plane = s.doc.plane.has_value();
    const bool vdb = meshFormat(o.output) == ".vdb";
    bool edited = false;
    ImGui::BeginDisabled(running);
    edited |= formatCombo(o);
    noteWidgetRect(s.layout, "meshExport:Format");
    edited |= ImGui::InputText("File", &o.output);
    noteWidgetRect(s.layout, "meshExport:File");
    helpMarker("The file's extension picks the format (.ply, .glb, .obj, .stl, .vdb); the Format list changes it.");
    sectionHeader("Detail");
    edited |= dragClamped("Resolution", &o.resolution, 1, 2.0f, 16, 4096, "%d voxels across");
    noteWidgetRect(s.layout, "meshExport:Resolution");
    helpMarker(
        "Voxels across the formula's bound: the finest detail the mesh keeps. Twice the resolution is four to six "
        "times the triangles, the memory and the time (a fractal's surface grows faster than a smooth one's).");
    const double voxel = plane ? 0.0 : meshVoxelSize(s.doc.preset.formula, o.resolution);
    if (!plane)
        ImGui::TextDisabled("Voxel %.4g in the preset's units (the bound is %.4g across).", voxel,
                            2.0 * s.doc.preset.formula.boundRadius);
    edited |= dragClamped("Simplify", &o.simplify, 1, 0.005f, 0.0, 1.0, "%.2f");
    noteWidgetRect(s.layout, "meshExport:Simplify");
    helpMarker("Merges flat regions into larger polygons (OpenVDB's adaptivity): 0 keeps every voxel's facet.");
    sectionHeader("Printing");
    ImGui::BeginDisabled(vdb);
    edited |= ImGui::InputTextWithHint("Print size (mm)", "preset units", &o.printSizeMm);
    ImGui::EndDisabled();
    noteWidgetRect(s.layout, "meshExport:Print size");
    helpMarker(vdb ? "A level set keeps the preset's units (its voxel size): no print size."
                   : "The mesh's largest side, in millimetres. Empty: the preset's units.");
    edited |= ImGui::Checkbox("Remove cavities", &o.removeCavities);
    noteWidgetRect(s.layout, "meshExport:Remove cavities");
    helpMarker(
        "Keeps only the surface seen from outside: the closed cavities inside the fractal (and what floats in "
        "them) are filled, as a print would trap them (resin, powder).");
    edited |= dragClamped("Min thickness", &o.minThickness, 1, float(std::max(voxel, 1e-4) * 0.25), 0.0,
                          2.0 * (plane ? 1.0 : s.doc.preset.formula.boundRadius), "%.4g");
    noteWidgetRect(s.layout, "meshExport:Min thickness");
    helpMarker(
        "Parts thinner than this, in the preset's units, are thickened to it: a nozzle's width or a resin's "
        "finest wall at the print size. 0: as they are.");
    if (o.minThickness > 0.0 && voxel > 0.0)
        ImGui::TextDisabled(
            o.minThickness < voxel ? "%.2g voxels: under a voxel, the mesh cannot show it." : "%.3g voxels.",
            o.minThickness / voxel);
    const bool colours = meshFormatCarriesColours(o.output);
    ImGui::BeginDisabled(!colours);
    bool shownColours = colours && o.vertexColours;
    if (ImGui::Checkbox("Vertex colours", &shownColours)) {
        o.vertexColours = shownColours;
        edited = true;
    }
    ImGui::EndDisabled();
    noteWidgetRect(s.layout, "meshExport:Vertex colours");
    helpMarker(colours ? "The preset's palette on the vertices, for a colour print or a viewer."
                       : "STL and the level set carry no colours: PLY, OBJ and glTF do.");
    ImGui::EndDisabled();
    // A finished job's Done, Failed or Cancelled speaks of its own file, not of the options now.
    if (edited) exportOptionsEdited(job);

    const std::string error = meshOptionsError(o, plane);
    if (!error.empty()) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "%s", error.c_str());
        noteWidgetRect(s.layout, "meshExport:Error");
    }
    ImGui::Spacing();
    if (!running) {
        ImGui::BeginDisabled(!error.empty());
        if (ImGui::Button("Export", ImVec2(120, 0))) startMeshExport(job, exportPresetText(s.doc, s.file.path), s.now);
        ImGui::EndDisabled();
        noteWidgetRect(s.layout, "meshExport:Export");
    } else {
        ImGui::BeginDisabled(job.status == ExportStatus::Cancelling);
        if (ImGui::Button("Cancel", ImVec2(120, 0))) cancelExport(job);
        ImGui::EndDisabled();
        noteWidgetRect(s.layout, "meshExport:Cancel");
    }
    ImGui::SameLine();
    drawExportProgress(job, meshExportStatusText(job), meshProgressStage(job.log), "meshing", s.now);
    noteWidgetRect(s.layout, "meshExport:Status");
    drawExportLog(s, job, commandLine(meshExportCommand("fraktal", "<preset>", o)), "meshExport:Command and log");
    endExportDialog();
}

}  // namespace fraktal::editor
