// The Shading tab: the preset's `shading` section (core/render_settings.hpp), which the viewport
// and the still export both read. Colours are linear Rec.709 as the preset stores them.
#include <imgui.h>

#include <iterator>

#include "app/editor/panels/panels.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/setting_widgets.hpp"

namespace fraktal::editor {

namespace {

std::vector<double> keyValue(const vec3& v) { return {v.x, v.y, v.z}; }

void drawLightSection(EditorState& s, ShadingSettings& sh) {
    sectionHeader("Light");
    keyMarker(s, "shading.lightDirection", keyValue(sh.lightDirection));
    directionEdit("Light direction", sh.lightDirection, "Where the main light comes from.");
    keyMarker(s, "shading.lightColor", keyValue(sh.lightColor));
    colorEdit("Light colour", sh.lightColor, "The main light's colour; above 1 is brighter.");
    keyMarker(s, "shading.fillColor", keyValue(sh.fillColor));
    colorEdit("Fill colour", sh.fillColor, "The soft light from the sky that fills the shadows.");
    keyMarker(s, "shading.specular", {sh.specular});
    dragDouble("Specular", sh.specular, 0.0, 4.0, 0.005f, "%.3f", nullptr);
    keyMarker(s, "shading.shininess", {sh.shininess});
    dragDouble("Shininess", sh.shininess, 1.0, 1000.0, 0.5f, "%.1f", nullptr);
    bool shadows = sh.shadowSteps > 0;
    if (ImGui::Checkbox("Shadows", &shadows)) sh.shadowSteps = shadows ? ShadingSettings{}.shadowSteps : 0;
    if (shadows) {
        dragInt("Shadow steps", sh.shadowSteps, 1, 1000, 0.5f,
                "How far shadows are traced: more catches thin shadow casters.");
        keyMarker(s, "shading.shadowSoftness", {sh.shadowSoftness});
        dragDouble("Shadow softness", sh.shadowSoftness, 0.5, 200.0, 0.1f, "%.1f",
                   "How sharp the edges of shadows are: larger is sharper.");
    }
    bool ao = sh.aoSteps > 0;
    if (ImGui::Checkbox("Ambient occlusion", &ao)) sh.aoSteps = ao ? ShadingSettings{}.aoSteps : 0;
    if (ao) {
        dragInt("AO steps", sh.aoSteps, 1, 32, 0.1f, nullptr);
        keyMarker(s, "shading.aoDistance", {sh.aoDistance});
        dragDouble("AO distance", sh.aoDistance, 0.001, 1.0, 0.001f, "%.3f x bound", nullptr);
        keyMarker(s, "shading.aoStrength", {sh.aoStrength});
        dragDouble("AO strength", sh.aoStrength, 0.0, 4.0, 0.01f, "%.2f", nullptr);
    }
}

void drawPaletteSection(EditorState& s, ShadingSettings& sh) {
    sectionHeader("Orbit-trap palette");
    paletteChoice(sh.paletteA, sh.paletteB, sh.paletteC, sh.paletteD);
    helpMarker(
        "Colours the surface by how close each point's orbit came to three planes and to the centre (the trap "
        "weights say how much each counts), times the trap scale plus the trap offset, looked up in a palette "
        "of waves: a is the base colour, b how far it swings, c how often it cycles, d where it starts.");
    double w[4] = {sh.trapWeights.x, sh.trapWeights.y, sh.trapWeights.z, sh.trapWeights.w};
    if (dragClamped("Trap weights", w, 4, 0.005f, -4.0, 4.0, "%.2f")) sh.trapWeights = vec4(w[0], w[1], w[2], w[3]);
    keyMarker(s, "shading.trapScale", {sh.trapScale});
    dragDouble("Trap scale", sh.trapScale, -20.0, 20.0, 0.01f, "%.3f", nullptr);
    keyMarker(s, "shading.trapOffset", {sh.trapOffset});
    dragDouble("Trap offset", sh.trapOffset, -4.0, 4.0, 0.005f, "%.3f", nullptr);
    paletteTerms(sh.paletteA, sh.paletteB, sh.paletteC, sh.paletteD);
}

void drawAtmosphereSection(EditorState& s, ShadingSettings& sh) {
    sectionHeader("Fog, reflection, background");
    keyMarker(s, "shading.fogDensity", {sh.fogDensity});
    dragDouble("Fog density", sh.fogDensity, 0.0, 20.0, 0.005f, "%.3f", "How thick the fog is (0: no fog).");
    keyMarker(s, "shading.fogColor", keyValue(sh.fogColor));
    colorEdit("Fog colour", sh.fogColor, nullptr);
    keyMarker(s, "shading.reflection", {sh.reflection});
    dragDouble("Reflection", sh.reflection, 0.0, 1.0, 0.002f, "%.3f",
               "How much the surface mirrors its surroundings (0: not at all).");
    colorEdit("Background top", sh.backgroundTop, nullptr);
    colorEdit("Background bottom", sh.backgroundBottom, nullptr);
}

}  // namespace

void drawShadingTab(EditorState& s) {
    ShadingSettings& sh = s.doc.preset.shading;
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    drawLightSection(s, sh);
    drawPaletteSection(s, sh);
    drawAtmosphereSection(s, sh);
    ImGui::PopItemWidth();
    ImGui::Spacing();
    if (ImGui::Button("Reset shading to defaults")) sh = ShadingSettings{};
}

}  // namespace fraktal::editor
