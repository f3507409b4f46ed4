// The formula panel (left): iterations and bailout, the node list (select, enable, reorder by
// drag and drop, duplicate, remove, add from a categorised menu), the estimator, and the
// selected node's parameters. Compile errors are shown under the node they name.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <string>

#include "app/editor/formula_edits.hpp"
#include "app/editor/panels.hpp"
#include "app/editor/param_widgets.hpp"

namespace fraktal::editor {

namespace {

constexpr const char* kNodePayload = "FRAKTAL_NODE";
const ImVec4 kErrorColor(1.0f, 0.42f, 0.36f, 1.0f);

std::string nodeLabel(const Node& n, int index) {
    std::string label = std::to_string(index + 1) + ". " + std::string(n.block->label);
    if (n.period > 1) label += "  (iter % " + std::to_string(n.period) + " = " + std::to_string(n.phase) + ")";
    return label;
}

void addBlockMenu(EditorState& s) {
    Formula& f = s.doc.preset.formula;
    const Category steps[] = {Category::Fold, Category::Transform, Category::Power};
    for (Category c : steps) {
        if (!ImGui::BeginMenu(std::string(categoryName(c)).c_str())) continue;
        for (const BlockDesc* b : blocksIn(c)) {
            if (ImGui::MenuItem(std::string(b->label).c_str())) {
                const int at = std::min(s.selectedNode + 1, int(f.nodes.size()));
                if (addNode(f, *b, at)) s.selectedNode = at;
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(b->help).c_str());
        }
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::BeginMenu("Estimator (replaces)")) {
        for (const BlockDesc* b : blocksIn(Category::Estimator)) {
            if (ImGui::MenuItem(std::string(b->label).c_str(), nullptr, f.estimator.block == b)) {
                setEstimator(f, *b);
                s.selectedNode = int(f.nodes.size());
            }
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(b->help).c_str());
        }
        ImGui::EndMenu();
    }
}

void errorUnder(const std::string& error) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(error.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

void globalSettings(Formula& f) {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    ImGui::DragInt("Iterations", &f.iterations, 0.1f, 1, kMaxIterations, "%d", ImGuiSliderFlags_AlwaysClamp);
    helpMarker("How many times the node list runs per point. Parameters update live, without a recompile.");
    const double bailLo = 0.1, bailHi = 1e6, boundLo = 0.01, boundHi = 100.0, facLo = 0.01, facHi = 1.0;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    ImGui::DragScalar("Bailout", ImGuiDataType_Double, &f.bailout, 0.05f, &bailLo, &bailHi, "%.4g",
                      ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
    helpMarker("The orbit escapes when |p| passes this radius.");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    ImGui::DragScalar("Bound radius", ImGuiDataType_Double, &f.boundRadius, 0.01f, &boundLo, &boundHi, "%.3g",
                      ImGuiSliderFlags_AlwaysClamp);
    helpMarker("The fractal lies inside this sphere; rays are clipped to it.");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    ImGui::DragScalar("DE factor", ImGuiDataType_Double, &f.deFactor, 0.005f, &facLo, &facHi, "%.3f",
                      ImGuiSliderFlags_AlwaysClamp);
    helpMarker("Multiplies the distance estimate: below 1 makes an overshooting hybrid safe (see fraktal check).");
}

// One row of the node list; returns the index to remove / duplicate through the out params.
void nodeRow(EditorState& s, int i, int errorNode, const std::string& error, int& remove, int& duplicate,
             int& moveFrom, int& moveTo) {
    Formula& f = s.doc.preset.formula;
    Node& n = f.nodes[size_t(i)];
    ImGui::PushID(i);
    ImGui::Checkbox("##on", &n.enabled);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(n.enabled ? "Disable this node" : "Enable this node");
    ImGui::SameLine();
    const float buttons = ImGui::CalcTextSize("DupDel").x + ImGui::GetStyle().FramePadding.x * 4 +
                          ImGui::GetStyle().ItemSpacing.x * 2;
    if (!n.enabled) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (i == errorNode) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    if (ImGui::Selectable(nodeLabel(n, i).c_str(), s.selectedNode == i, 0,
                          ImVec2(ImGui::GetContentRegionAvail().x - buttons, 0)))
        s.selectedNode = i;
    if (i == errorNode) ImGui::PopStyleColor();
    if (!n.enabled) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\nDrag to reorder.", std::string(n.block->help).c_str());
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(kNodePayload, &i, sizeof i);
        ImGui::TextUnformatted(nodeLabel(n, i).c_str());
        ImGui::EndDragDropSource();
    }
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload(kNodePayload)) {
            moveFrom = *static_cast<const int*>(p->Data);
            moveTo = i;
        }
        ImGui::EndDragDropTarget();
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("Dup")) duplicate = i;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Duplicate this node (Ctrl+D)");
    ImGui::SameLine();
    if (ImGui::SmallButton("Del")) remove = i;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this node (Delete)");
    if (i == errorNode) errorUnder(error);
    ImGui::PopID();
}

void selectedNodeEditor(EditorState& s) {
    Formula& f = s.doc.preset.formula;
    const bool estimator = s.selectedNode == int(f.nodes.size());
    Node& n = estimator ? f.estimator : f.nodes[size_t(s.selectedNode)];
    if (!n.block) return;
    ImGui::Text("%s", std::string(n.block->label).c_str());
    ImGui::SameLine();
    ImGui::TextDisabled("%s", std::string(categoryName(n.block->category)).c_str());
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", std::string(n.block->help).c_str());
    ImGui::PopTextWrapPos();
    if (!estimator) {
        // Period and phase decide on which iterations the node runs (hybrids): structure edits.
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.3f);
        if (ImGui::InputInt("Period", &n.period, 1, 1)) n.period = std::clamp(n.period, 1, 16);
        helpMarker("The node runs on iterations i with i % period == phase (hybrids alternate blocks).");
        ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.3f);
        if (ImGui::InputInt("Phase", &n.phase, 1, 1)) n.phase = std::clamp(n.phase, 0, n.period - 1);
        n.phase = std::clamp(n.phase, 0, n.period - 1);
    }
    if (n.block->params.empty()) ImGui::TextDisabled("This block has no parameters.");
    for (size_t k = 0; k < n.block->params.size(); ++k) paramWidget(n.block->params[k], n.values[k]);
}

}  // namespace

void drawFormulaPanel(EditorState& s, const ViewportView& v) {
    if (!s.panels.formula) return;
    const ImGuiViewport* vp = ImGui::GetMainViewport();
    const float height = vp->WorkSize.y;
    ImGui::SetNextWindowPos(ImVec2(vp->WorkPos.x, vp->WorkPos.y));
    ImGui::SetNextWindowSizeConstraints(ImVec2(260, height), ImVec2(vp->WorkSize.x * 0.45f, height));
    ImGui::SetNextWindowSize(ImVec2(s.layout.leftWidth, height), ImGuiCond_FirstUseEver);
    ImGui::Begin("Formula", &s.panels.formula, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse);
    s.layout.leftWidth = ImGui::GetWindowWidth();
    Formula& f = s.doc.preset.formula;
    s.selectedNode = std::clamp(s.selectedNode, 0, int(f.nodes.size()));

    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##name", "Preset name", &s.doc.preset.name);
    globalSettings(f);
    ImGui::Spacing();
    sectionHeader("Node list");

    const std::string& error = v.compileError();
    const int errorNode = error.empty() ? -2 : nodeNamedInLog(error, int(f.nodes.size()));
    int remove = -1, duplicate = -1, moveFrom = -1, moveTo = -1;
    for (int i = 0; i < int(f.nodes.size()); ++i) nodeRow(s, i, errorNode, error, remove, duplicate, moveFrom, moveTo);

    // The estimator closes the list; it is always last and cannot be removed, only replaced.
    ImGui::PushID("estimator");
    const int est = int(f.nodes.size());
    if (errorNode == est) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    if (ImGui::Selectable(("=> " + std::string(f.estimator.block ? f.estimator.block->label : "(none)")).c_str(),
                          s.selectedNode == est))
        s.selectedNode = est;
    if (errorNode == est) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The closing estimator: turns the final orbit into a distance.");
    if (errorNode == est) errorUnder(error);
    ImGui::PopID();
    if (!error.empty() && errorNode == -1) errorUnder(error);

    if (ImGui::Button("Add block...")) ImGui::OpenPopup("add_block");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Insert a block after the selected node");
    if (ImGui::BeginPopup("add_block")) {
        addBlockMenu(s);
        ImGui::EndPopup();
    }
    const bool nodeSelected = s.selectedNode < int(f.nodes.size());
    ImGui::SameLine();
    ImGui::BeginDisabled(!nodeSelected || s.selectedNode == 0);
    if (ImGui::ArrowButton("##up", ImGuiDir_Up)) moveFrom = s.selectedNode, moveTo = s.selectedNode - 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!nodeSelected || s.selectedNode + 1 >= int(f.nodes.size()));
    if (ImGui::ArrowButton("##down", ImGuiDir_Down)) moveFrom = s.selectedNode, moveTo = s.selectedNode + 1;
    ImGui::EndDisabled();

    // Apply list edits after drawing the list, so no row is drawn from a moved vector.
    if (moveFrom >= 0 && moveNode(f, moveFrom, moveTo)) s.selectedNode = moveTo;
    if (duplicate >= 0 && duplicateNode(f, duplicate)) s.selectedNode = duplicate + 1;
    if (remove >= 0 && removeNode(f, remove)) s.selectedNode = std::max(0, std::min(remove, int(f.nodes.size()) - 1));
    s.selectedNode = std::clamp(s.selectedNode, 0, int(f.nodes.size()));

    ImGui::Spacing();
    sectionHeader("Parameters");
    selectedNodeEditor(s);
    ImGui::End();
}

}  // namespace fraktal::editor
