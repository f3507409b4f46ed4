#include "app/editor/widgets/param_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace fraktal::editor {

namespace {

std::string defaultText(const ParamDecl& d) {
    if (d.type == ParamType::Toggle) return d.defaultValue.x > 0.5 ? "on" : "off";
    if (d.type == ParamType::Float) return std::to_string(d.defaultValue.x);
    return std::to_string(d.defaultValue.x) + ", " + std::to_string(d.defaultValue.y) + ", " +
           std::to_string(d.defaultValue.z);
}

void tooltip(const ParamDecl& d, ParamWidgetsShown* shown) {
    if (!ImGui::IsItemHovered()) return;
    ImGui::BeginTooltip();
    ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
    const std::string help(d.help);
    ImGui::TextUnformatted(help.c_str());
    if (d.type == ParamType::Toggle) {
        ImGui::TextDisabled("on or off, default %s", defaultText(d).c_str());
    } else {
        ImGui::TextDisabled("range %.4g .. %.4g, default %s", d.min, d.max, defaultText(d).c_str());
        ImGui::TextDisabled("Ctrl+click to type a value");
    }
    ImGui::PopTextWrapPos();
    ImGui::EndTooltip();
    if (shown) {
        shown->tooltipParam = std::string(d.name);
        shown->tooltip = help;
    }
}

}  // namespace

void helpMarker(const char* help) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    if (ImGui::IsItemHovered()) {
        ImGui::BeginTooltip();
        ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
        ImGui::TextUnformatted(help);
        ImGui::PopTextWrapPos();
        ImGui::EndTooltip();
    }
}

void sectionHeader(const char* title) {
    ImGui::Spacing();
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextUnformatted(title);
    ImGui::PopStyleColor();
    ImGui::Separator();
}

void ParamWidgetsShown::noteLastItem(std::string name) {
    const ImVec2 at = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
    widgets.push_back({std::move(name), at.x, at.y, size.x, size.y});
}

bool paramWidget(const ParamDecl& d, ParamValue& value, ParamWidgetsShown* shown) {
    const std::string name(d.name);
    ImGui::PushID(name.c_str());
    bool changed = false;
    const double lo = d.min, hi = d.max;
    // About 400 pixels of drag across the range; fine control with Alt (ImGui's slow modifier).
    const float speed = float(std::max((hi - lo) / 400.0, 1e-6));
    const float resetWidth = ImGui::GetFrameHeight();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - resetWidth - ImGui::GetStyle().ItemInnerSpacing.x -
                            ImGui::CalcTextSize(name.c_str()).x - ImGui::GetStyle().ItemInnerSpacing.x);
    const ImGuiSliderFlags flags = ImGuiSliderFlags_AlwaysClamp;
    if (d.type == ParamType::Toggle) {
        // One click flips it: the checkbox is active for that frame only, so the editor commits
        // one undo step per click.
        bool on = value.x > 0.5;
        if (ImGui::Checkbox("##v", &on)) {
            value = vec3(on ? 1.0 : 0.0, 0.0, 0.0);
            changed = true;
        }
    } else if (d.type == ParamType::Float) {
        changed = ImGui::DragScalar("##v", ImGuiDataType_Double, &value.x, speed, &lo, &hi, "%.4g", flags);
    } else {
        double v[3] = {value.x, value.y, value.z};
        changed = ImGui::DragScalarN("##v", ImGuiDataType_Double, v, 3, speed, &lo, &hi, "%.3g", flags);
        if (changed) {
            const vec3 next(v[0], v[1], v[2]);
            // A direction may not be zero: refuse the edit that would make it so.
            if (d.direction && length(next) == 0.0)
                changed = false;
            else
                value = next;
        }
    }
    if (shown) shown->noteLastItem(name);
    tooltip(d, shown);
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    const bool isDefault = value == d.defaultValue;
    ImGui::BeginDisabled(isDefault);
    if (ImGui::Button("<", ImVec2(resetWidth, 0))) {
        value = d.defaultValue;
        changed = true;
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("Reset to default");
    ImGui::EndDisabled();
    ImGui::SameLine(0, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextUnformatted(name.c_str());
    tooltip(d, shown);
    ImGui::PopID();
    return changed;
}

}  // namespace fraktal::editor
