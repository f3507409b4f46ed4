// The Formula panel of a 2D document (left): iterations and bailout, the start list (runs
// once: the Koch snowflake's fold into a side's frame), the loop list, the estimator, and the
// selected node's parameters, with the same row and parameter widgets as the 3D panel
// (node_list_widgets.hpp). Compile errors are shown under the node they name.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <string>

#include "app/editor/document/node_list_edits.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/state/plane_edits.hpp"
#include "app/editor/widgets/node_list_widgets.hpp"
#include "app/editor/widgets/param_widgets.hpp"

namespace fraktal::editor {

namespace {

void addBlockMenu(EditorState& s) {
    PlaneFormula& f = s.doc.plane->formula;
    for (Category c : {Category::Fold, Category::Transform, Category::Power}) {
        if (!ImGui::BeginMenu(std::string(categoryName(c)).c_str())) continue;
        if (const PlaneBlockDesc* b = blockMenuItems(planeBlocksIn(c)))
            s.planeSelection = addPlaneBlock(f, *b, s.planeSelection);
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::BeginMenu("Estimator (replaces)")) {
        if (const PlaneBlockDesc* b = blockMenuItems(planeBlocksIn(Category::Estimator), f.estimator.block))
            s.planeSelection = addPlaneBlock(f, *b, s.planeSelection);
        ImGui::EndMenu();
    }
}

void globalSettings(PlaneFormula& f) {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    dragClamped("Iterations", &f.iterations, 1, 0.2f, 0, kMaxIterations, "%d");
    helpMarker(
        "How many times the loop runs per point (the depth of the Sierpinski and Koch tests). Parameters "
        "update live, without a recompile.");
    const double lo = 1e-3, hi = 1e10;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    dragClamped("Bailout", &f.bailout, 1, 0.05f, lo, hi, "%.4g", ImGuiSliderFlags_Logarithmic);
    helpMarker("The orbit escapes when |z| passes this radius (2 for the Mandelbrot set; larger colours smoothly).");
}

// One list (start or loop) with its rows; the edits the rows ask for are applied after drawing.
void nodeList(EditorState& s, PlaneList which, const char* payload, const std::optional<PlaneSelection>& errorAt,
              const std::string& error) {
    std::vector<PlaneNode>& list = *planeList(s.doc.plane->formula, which);
    NodeListRequest req;
    PlaneSelection& sel = s.planeSelection;
    ImGui::PushID(payload);
    for (int i = 0; i < int(list.size()); ++i) {
        const PlaneSelection here{which, i};
        const bool failed = errorAt && *errorAt == here;
        if (nodeRow(list[size_t(i)], i, sel == here, failed ? &error : nullptr, payload, req)) sel = here;
    }
    if (list.empty()) ImGui::TextDisabled("(empty)");
    ImGui::PopID();
    if (sel.list == which && validNodeIndex(list, sel.index)) {
        // Up/down arrows for the selected node, as in the 3D panel.
        ImGui::PushID(payload);
        ImGui::BeginDisabled(sel.index == 0);
        if (ImGui::ArrowButton("##up", ImGuiDir_Up)) req.moveFrom = sel.index, req.moveTo = sel.index - 1;
        ImGui::EndDisabled();
        ImGui::SameLine();
        ImGui::BeginDisabled(sel.index + 1 >= int(list.size()));
        if (ImGui::ArrowButton("##down", ImGuiDir_Down)) req.moveFrom = sel.index, req.moveTo = sel.index + 1;
        ImGui::EndDisabled();
        ImGui::PopID();
    }
    if (req.moveFrom >= 0 && moveNodeWithin(list, req.moveFrom, req.moveTo)) sel = {which, req.moveTo};
    if (req.duplicate >= 0 && duplicateNodeAt(list, req.duplicate)) sel = {which, req.duplicate + 1};
    if (req.remove >= 0 && removeNodeAt(list, req.remove)) sel = {which, req.remove};
}

}  // namespace

void drawPlaneFormulaPanel(EditorState& s, const std::string& error) {
    if (!sideColumnShows(s.panels, true) || !s.doc.plane) return;
    beginFormulaWindow(s);
    PlanePreset& p = *s.doc.plane;
    PlaneFormula& f = p.formula;
    s.planeSelection = clampedSelection(f, s.planeSelection);

    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##name", "Preset name", &p.name);
    ImGui::TextDisabled("2D formula");
    globalSettings(f);

    const std::optional<PlaneSelection> errorAt = error.empty() ? std::nullopt : planeNodeNamedInLog(error);
    sectionHeader("Start (runs once)");
    nodeList(s, PlaneList::Start, "FRAKTAL_PLANE_START", errorAt, error);
    sectionHeader("Loop (every iteration)");
    nodeList(s, PlaneList::Loop, "FRAKTAL_PLANE_LOOP", errorAt, error);

    // The estimator closes the formula; it cannot be removed, only replaced.
    const bool estimatorFailed = errorAt && errorAt->list == PlaneList::Estimator;
    if (estimatorFailed) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    if (ImGui::Selectable(("=> " + std::string(f.estimator.block ? f.estimator.block->label : "(none)")).c_str(),
                          s.planeSelection.list == PlaneList::Estimator))
        s.planeSelection = {PlaneList::Estimator, 0};
    if (estimatorFailed) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The closing estimator: decides membership and the distance.");
    if (estimatorFailed) errorUnder(error);
    if (!error.empty() && !errorAt) errorUnder(error);

    if (ImGui::Button("Add block...")) ImGui::OpenPopup("add_plane_block");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Insert a 2D block after the selected node");
    if (ImGui::BeginPopup("add_plane_block")) {
        addBlockMenu(s);
        ImGui::EndPopup();
    }
    s.planeSelection = clampedSelection(f, s.planeSelection);

    ImGui::Spacing();
    sectionHeader("Parameters");
    if (PlaneNode* n = selectedPlaneNode(f, s.planeSelection))
        nodeParameters(*n, s.planeSelection.list == PlaneList::Estimator, s.paramWidgets);
    // A node selected with fewer parameters below it leaves the rows above where they were.
    keepWindowScroll();
    ImGui::End();
}

}  // namespace fraktal::editor
