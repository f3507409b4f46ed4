// The Formula panel's widgets for one node list, shared by the 3D formula (core/formula.hpp
// Node) and the 2D formula (core/plane/plane_formula.hpp PlaneNode): a row per node (enable,
// select, drag to reorder, duplicate, remove, a compile error under the node it names) and the
// selected node's period, phase and parameters (param_widgets.hpp, from the block's ParamDecl).
// Templates over the node type: both node types have block, values, enabled, period and phase.
#pragma once

#include <imgui.h>

#include <algorithm>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "app/editor/widgets/param_widgets.hpp"
#include "core/iteration_schedule.hpp"

namespace fraktal::editor {

inline const ImVec4 kErrorColor(1.0f, 0.42f, 0.36f, 1.0f);

// The list edits a frame's rows asked for; applied after the list is drawn, so that no row is
// drawn from a changed vector.
struct NodeListRequest {
    int remove = -1, duplicate = -1, moveFrom = -1, moveTo = -1;
};

// A compile error, wrapped, in the error colour.
void errorUnder(const std::string& error);

// When a node runs, counting iterations from 1 as the artist does: "every 2nd iteration from
// the 1st", "iterations 3 to 8", "every 3rd iteration from the 2nd, iterations 2 to 9".
std::string scheduleText(const IterationSchedule& s);

template <class NodeT>
std::string nodeLabel(const NodeT& n, int index) {
    std::string label = std::to_string(index + 1) + ". " + std::string(n.block->label);
    if (!n.always()) label += "  (" + scheduleText(n.schedule()) + ")";
    return label;
}

// One row of a node list. `payload` names the drag-and-drop type: rows reorder only within
// lists of the same payload. Returns whether the row was clicked (select it).
template <class NodeT>
bool nodeRow(NodeT& n, int i, bool selected, const std::string* error, const char* payload, NodeListRequest& req) {
    ImGui::PushID(i);
    ImGui::Checkbox("##on", &n.enabled);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip(n.enabled ? "Disable this node" : "Enable this node");
    ImGui::SameLine();
    const float buttons =
        ImGui::CalcTextSize("DupDel").x + ImGui::GetStyle().FramePadding.x * 4 + ImGui::GetStyle().ItemSpacing.x * 2;
    if (!n.enabled) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    if (error) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    const bool clicked =
        ImGui::Selectable(nodeLabel(n, i).c_str(), selected, 0, ImVec2(ImGui::GetContentRegionAvail().x - buttons, 0));
    if (error) ImGui::PopStyleColor();
    if (!n.enabled) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s\nDrag to reorder.", std::string(n.block->help).c_str());
    if (ImGui::BeginDragDropSource()) {
        ImGui::SetDragDropPayload(payload, &i, sizeof i);
        ImGui::TextUnformatted(nodeLabel(n, i).c_str());
        ImGui::EndDragDropSource();
    }
    if (ImGui::BeginDragDropTarget()) {
        if (const ImGuiPayload* p = ImGui::AcceptDragDropPayload(payload)) {
            req.moveFrom = *static_cast<const int*>(p->Data);
            req.moveTo = i;
        }
        ImGui::EndDragDropTarget();
    }
    ImGui::SameLine();
    if (ImGui::SmallButton("Dup")) req.duplicate = i;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Duplicate this node (Ctrl+D)");
    ImGui::SameLine();
    if (ImGui::SmallButton("Del")) req.remove = i;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Remove this node (Delete)");
    if (error) errorUnder(*error);
    ImGui::PopID();
    return clicked;
}

// Whether `word` is one of the words of `text`, case aside.
inline bool containsWord(std::string_view text, std::string_view word) {
    auto lower = [](char c) { return char(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c); };
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find(' ', start), text.size());
        const std::string_view w = text.substr(start, end - start);
        if (w.size() == word.size() &&
            std::equal(w.begin(), w.end(), word.begin(), [&](char a, char b) { return lower(a) == lower(b); }))
            return true;
        start = end + 1;
    }
    return false;
}

// The selected node's block, help, period and phase (not for estimators) and parameters;
// `beforeParam(k)` draws what goes before parameter k's widget on its line (a key marker);
// `shown` records the widgets (ParamWidgetsShown). `groupOf(k)` names parameter k's group (an
// imported frag's #group): a heading goes above the first parameter of each run of one group.
template <class NodeT>
void nodeParameters(NodeT& n, bool estimator, ParamWidgetsShown& shown,
                    const std::function<void(size_t)>& beforeParam = {},
                    const std::function<std::string(size_t)>& groupOf = {}) {
    if (!n.block) return;
    const std::string label(n.block->label), category(categoryName(n.block->category));
    ImGui::Text("%s", label.c_str());
    // The kind of block beside its name, unless the name says it ("Mandelbulb power", not
    // "Mandelbulb power power").
    if (!containsWord(label, category)) {
        ImGui::SameLine();
        ImGui::TextDisabled("%s", category.c_str());
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", std::string(n.block->help).c_str());
    ImGui::PopTextWrapPos();
    if (!estimator) {
        // The schedule decides on which iterations the node runs (hybrids, a block on the first
        // iterations only): structure edits. Two lines, so that the parameters keep their place.
        const float field = ImGui::GetContentRegionAvail().x * 0.22f;
        ImGui::SetNextItemWidth(field);
        inputClamped("Period", &n.period, 1, 1, 1, kMaxPeriod);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(field);
        inputClamped("Phase", &n.phase, 1, 1, 0, n.period - 1);
        n.phase = std::clamp(n.phase, 0, n.period - 1);
        helpMarker("The node runs on iterations i with i % period == phase (hybrids alternate blocks).");
        ImGui::SetNextItemWidth(field);
        inputClamped("From", &n.start, 1, 10, 0, kMaxIterations - 1);
        shown.noteLastItem("schedule:From");
        ImGui::SameLine();
        bool untilSet = n.stop < kMaxIterations;
        if (ImGui::Checkbox("Before", &untilSet)) n.stop = untilSet ? n.start + 1 : kMaxIterations;
        shown.noteLastItem("schedule:Before");
        if (untilSet) {
            ImGui::SameLine();
            ImGui::SetNextItemWidth(field);
            inputClamped("##stop", &n.stop, 1, 10, 1, kMaxIterations - 1, "Before");
            shown.noteLastItem("schedule:Before iteration");
        }
        helpMarker(
            "The node runs from iteration From (the first is 0) and, ticked, only on iterations before "
            "Before's: a pre-transform on the first iterations.");
        n.stop = std::max(n.stop, n.start + 1);
    }
    if (n.block->params.empty()) ImGui::TextDisabled("This block has no parameters.");
    std::string group;
    for (size_t k = 0; k < n.block->params.size(); ++k) {
        if (const std::string g = groupOf ? groupOf(k) : std::string(); g != group) {
            group = g;
            if (!group.empty()) {
                sectionHeader(group.c_str());
                shown.groups.emplace_back(group, shown.widgets.size());
            }
        }
        if (beforeParam) beforeParam(k);
        paramWidget(n.block->params[k], n.values[k], &shown);
    }
}

// The "Add block" menu's items for one category's blocks; returns the one picked, or nullptr.
// `current` is ticked (the estimator in use). Blocks with a menu group follow in one submenu per
// group, in the order the groups first appear.
template <class BlockT>
const BlockT* blockMenuItems(const std::vector<const BlockT*>& blocks, const BlockT* current = nullptr) {
    const BlockT* picked = nullptr;
    auto items = [&](std::string_view group) {
        for (const BlockT* b : blocks) {
            if (b->menuGroup != group) continue;
            if (ImGui::MenuItem(std::string(b->label).c_str(), nullptr, current == b)) picked = b;
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(b->help).c_str());
        }
    };
    items({});
    std::vector<std::string_view> groups;
    for (const BlockT* b : blocks)
        if (!b->menuGroup.empty() && std::find(groups.begin(), groups.end(), b->menuGroup) == groups.end())
            groups.push_back(b->menuGroup);
    for (std::string_view group : groups)
        if (ImGui::BeginMenu(std::string(group).c_str())) {
            items(group);
            ImGui::EndMenu();
        }
    return picked;
}

}  // namespace fraktal::editor
