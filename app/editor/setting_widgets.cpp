#include "app/editor/setting_widgets.hpp"

#include <imgui.h>

#include "app/editor/param_widgets.hpp"

namespace fraktal::editor {

namespace {
void help(const char* text) {
    if (text) helpMarker(text);
}
}  // namespace

bool dragDouble(const char* label, double& value, double lo, double hi, float speed, const char* format,
                const char* helpText) {
    const bool changed =
        ImGui::DragScalar(label, ImGuiDataType_Double, &value, speed, &lo, &hi, format, ImGuiSliderFlags_AlwaysClamp);
    help(helpText);
    return changed;
}

bool dragInt(const char* label, int& value, int lo, int hi, float speed, const char* helpText) {
    const bool changed = ImGui::DragInt(label, &value, speed, lo, hi, "%d", ImGuiSliderFlags_AlwaysClamp);
    help(helpText);
    return changed;
}

bool colorEdit(const char* label, vec3& rgb, const char* helpText) {
    float c[3] = {float(rgb.x), float(rgb.y), float(rgb.z)};
    const bool changed = ImGui::ColorEdit3(label, c, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR);
    if (changed) rgb = vec3(std::max(c[0], 0.0f), std::max(c[1], 0.0f), std::max(c[2], 0.0f));
    help(helpText);
    return changed;
}

bool directionEdit(const char* label, vec3& direction, const char* helpText) {
    double v[3] = {direction.x, direction.y, direction.z};
    const double lo = -1.0, hi = 1.0;
    bool changed =
        ImGui::DragScalarN(label, ImGuiDataType_Double, v, 3, 0.01f, &lo, &hi, "%.2f", ImGuiSliderFlags_AlwaysClamp);
    const vec3 next(v[0], v[1], v[2]);
    if (changed && length(next) > 0.0)
        direction = next;
    else
        changed = false;
    help(helpText);
    return changed;
}

}  // namespace fraktal::editor
