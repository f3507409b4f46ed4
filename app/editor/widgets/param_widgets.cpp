#include "app/editor/widgets/param_widgets.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <type_traits>

#include "app/editor/widgets/text_fit.hpp"

namespace fraktal::editor {

namespace {

// The reports of the ReportClamps alive (null: none; clamps then go unreported).
ClampReports* gClampReports = nullptr;

// After a widget over `values` was drawn: brings what it changed into [lo, hi] and hands the
// clamp to the ReportClamps alive, named `name` (by default the label's visible text).
template <typename T>
void clampAndReport(ImGuiID id, const char* label, T* values, int count, T lo, T hi, bool changed,
                    std::string_view name) {
    std::optional<ClampNotice> notice;
    if (changed) {
        double v[4];
        std::copy(values, values + count, v);
        notice = clampIntoRange(name.empty() ? visibleLabel(label) : name, std::span(v, size_t(count)), double(lo),
                                double(hi), std::is_same_v<T, int>);
        for (int i = 0; i < count; ++i) values[i] = T(v[i]);
    }
    if (gClampReports) gClampReports->drawn(id, std::move(notice), changed, ImGui::IsItemDeactivated());
    checkItemFits(label);
}

template <typename T>
constexpr ImGuiDataType dataType() {
    return std::is_same_v<T, int> ? ImGuiDataType_S32 : ImGuiDataType_Double;
}

template <typename T>
bool dragClampedOf(const char* label, T* values, int count, float speed, T lo, T hi, const char* format, int flags,
                   std::string_view name) {
    const ImGuiID id = ImGui::GetID(label);
    flags &= ~ImGuiSliderFlags_AlwaysClamp;  // clamped below, where the typed value is still known
    const bool changed = count == 1
                             ? ImGui::DragScalar(label, dataType<T>(), values, speed, &lo, &hi, format, flags)
                             : ImGui::DragScalarN(label, dataType<T>(), values, count, speed, &lo, &hi, format, flags);
    clampAndReport(id, label, values, count, lo, hi, changed, name);
    return changed;
}

template <typename T>
bool inputClampedOf(const char* label, T* value, T step, T stepFast, T lo, T hi, const char* format,
                    std::string_view name) {
    const bool changed = ImGui::InputScalar(label, dataType<T>(), value, step > 0 ? &step : nullptr,
                                            stepFast > 0 ? &stepFast : nullptr, format);
    // The ID after the widget: ImGui 1.86's GetID keeps the active ID alive, and asked before the
    // input box's group (its +/- buttons) it hides the box's activity from the group, whose edit
    // then fails ImGui's MarkItemEdited assertion.
    clampAndReport(ImGui::GetID(label), label, value, 1, lo, hi, changed, name);
    return changed;
}

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

ReportClamps::ReportClamps(ClampReports& reports) : previous_(gClampReports) { gClampReports = &reports; }
ReportClamps::~ReportClamps() { gClampReports = previous_; }

bool dragClamped(const char* label, double* values, int count, float speed, double lo, double hi, const char* format,
                 int flags, std::string_view name) {
    return dragClampedOf(label, values, count, speed, lo, hi, format, flags, name);
}

bool dragClamped(const char* label, int* values, int count, float speed, int lo, int hi, const char* format, int flags,
                 std::string_view name) {
    return dragClampedOf(label, values, count, speed, lo, hi, format, flags, name);
}

bool inputClamped(const char* label, int* value, int step, int stepFast, int lo, int hi, std::string_view name) {
    return inputClampedOf(label, value, step, stepFast, lo, hi, "%d", name);
}

bool inputClamped(const char* label, double* value, double lo, double hi, const char* format, std::string_view name) {
    return inputClampedOf(label, value, 0.0, 0.0, lo, hi, format, name);
}

void helpMarker(const char* help) {
    ImGui::SameLine();
    ImGui::TextDisabled("(?)");
    checkItemFits("(?)");
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

void ParamWidgetsShown::noteLastItem(std::string name, std::string label) {
    const ImVec2 at = ImGui::GetItemRectMin(), size = ImGui::GetItemRectSize();
    if (label.empty()) label = name;
    widgets.push_back({std::move(name), std::move(label), at.x, at.y, size.x, size.y});
}

bool paramWidget(const ParamDecl& d, ParamValue& value, ParamWidgetsShown* shown) {
    const std::string name(d.name), label = paramLabel(d);
    ImGui::PushID(name.c_str());
    bool changed = false;
    const double lo = d.min, hi = d.max;
    // About 400 pixels of drag across the range; fine control with Alt (ImGui's slow modifier).
    const float speed = float(std::max((hi - lo) / 400.0, 1e-6));
    const float resetWidth = ImGui::GetFrameHeight();
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - resetWidth - ImGui::GetStyle().ItemInnerSpacing.x -
                            ImGui::CalcTextSize(label.c_str()).x - ImGui::GetStyle().ItemInnerSpacing.x);
    if (d.type == ParamType::Toggle) {
        // One click flips it: the checkbox is active for that frame only, so the editor commits
        // one undo step per click.
        bool on = value.x > 0.5;
        if (ImGui::Checkbox("##v", &on)) {
            value = vec3(on ? 1.0 : 0.0, 0.0, 0.0);
            changed = true;
        }
    } else if (d.type == ParamType::Float) {
        changed = dragClamped("##v", &value.x, 1, speed, lo, hi, "%.4g", 0, label);
    } else {
        double v[3] = {value.x, value.y, value.z};
        changed = dragClamped("##v", v, 3, speed, lo, hi, "%.3g", 0, label);
        if (changed) {
            const vec3 next(v[0], v[1], v[2]);
            // A direction may not be zero: refuse the edit that would make it so.
            if (d.direction && length(next) == 0.0)
                changed = false;
            else
                value = next;
        }
    }
    if (shown) shown->noteLastItem(name, label);
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
    ImGui::TextUnformatted(label.c_str());
    checkItemFits(label);
    tooltip(d, shown);
    ImGui::PopID();
    return changed;
}

}  // namespace fraktal::editor
