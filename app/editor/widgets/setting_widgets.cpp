#include "app/editor/widgets/setting_widgets.hpp"

#include <imgui.h>

#include "app/editor/widgets/param_widgets.hpp"

namespace fraktal::editor {

namespace {
void help(const char* text) {
    if (text) helpMarker(text);
}

// Cosine palettes colour = a + b cos(2 pi (c t + d)) (I. Quilez, "Palettes", 1999,
// iquilezles.org/articles/palettes): a starting point for the orbit-trap colouring.
struct NamedPalette {
    const char* name;
    vec3 a, b, c, d;
};
const NamedPalette kPalettes[] = {
    {"Ember (default)", {0.6, 0.5, 0.44}, {0.32, 0.26, 0.24}, {0.8, 0.8, 0.8}, {0.0, 0.15, 0.3}},
    {"Rainbow", {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {1.0, 1.0, 1.0}, {0.0, 0.33, 0.67}},
    {"Ocean", {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {1.0, 1.0, 1.0}, {0.0, 0.1, 0.2}},
    {"Copper", {0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, {1.0, 1.0, 0.5}, {0.8, 0.9, 0.3}},
    {"Bone", {0.55, 0.52, 0.48}, {0.12, 0.1, 0.08}, {1.0, 1.0, 1.0}, {0.0, 0.05, 0.1}},
};

bool vec3Drag(const char* label, vec3& v, double lo, double hi) {
    double x[3] = {v.x, v.y, v.z};
    if (!dragClamped(label, x, 3, 0.005f, lo, hi, "%.2f")) return false;
    v = vec3(x[0], x[1], x[2]);
    return true;
}
}  // namespace

bool paletteChoice(vec3& a, vec3& b, vec3& c, vec3& d) {
    bool changed = false;
    if (ImGui::BeginCombo("Palette", "Choose a starting point")) {
        for (const NamedPalette& p : kPalettes)
            if (ImGui::Selectable(p.name)) {
                a = p.a;
                b = p.b;
                c = p.c;
                d = p.d;
                changed = true;
            }
        ImGui::EndCombo();
    }
    return changed;
}

bool paletteTerms(vec3& a, vec3& b, vec3& c, vec3& d) {
    bool changed = colorEdit("a (base)", a, nullptr);
    changed |= colorEdit("b (swing)", b, nullptr);
    changed |= vec3Drag("c (frequency)", c, 0.0, 8.0);
    changed |= vec3Drag("d (phase)", d, -1.0, 1.0);
    return changed;
}

bool dragDouble(const char* label, double& value, double lo, double hi, float speed, const char* format,
                const char* helpText) {
    const bool changed = dragClamped(label, &value, 1, speed, lo, hi, format);
    help(helpText);
    return changed;
}

bool dragInt(const char* label, int& value, int lo, int hi, float speed, const char* helpText) {
    const bool changed = dragClamped(label, &value, 1, speed, lo, hi, "%d");
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
    bool changed = dragClamped(label, v, 3, 0.01f, -1.0, 1.0, "%.2f");
    const vec3 next(v[0], v[1], v[2]);
    if (changed && length(next) > 0.0)
        direction = next;
    else
        changed = false;
    help(helpText);
    return changed;
}

}  // namespace fraktal::editor
