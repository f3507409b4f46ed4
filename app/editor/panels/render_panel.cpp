// The Render tab: the viewport's budget (the document's ViewSettings), the march settings of the
// preset's `render` section, and its colour settings: working space, OCIO display and view and
// exposure. The viewport and the still export read the same preset fields, so what the viewport
// shows is what the export writes.
#include <imgui.h>

#include <string>
#include <vector>

#include "app/editor/panels/panels.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/setting_widgets.hpp"
#include "core/safe_step.hpp"

namespace fraktal::editor {

namespace {

// A combo over `names` editing `value`; true when the user picked another one.
bool nameCombo(const char* label, std::string& value, const std::vector<std::string>& names) {
    bool changed = false;
    if (ImGui::BeginCombo(label, value.c_str())) {
        for (const std::string& n : names)
            if (ImGui::Selectable(n.c_str(), n == value) && n != value) {
                value = n;
                changed = true;
            }
        ImGui::EndCombo();
    }
    return changed;
}

std::vector<std::string> displaysOf(const OCIO::ConstConfigRcPtr& c) {
    std::vector<std::string> out;
    for (int i = 0; i < c->getNumDisplays(); ++i) out.emplace_back(c->getDisplay(i));
    return out;
}

std::vector<std::string> viewsOf(const OCIO::ConstConfigRcPtr& c, const std::string& display) {
    std::vector<std::string> out;
    for (int i = 0; i < c->getNumViews(display.c_str()); ++i) out.emplace_back(c->getView(display.c_str(), i));
    return out;
}

// Scene-linear candidates: the role and every non-data colour space of the scene family.
std::vector<std::string> workingSpacesOf(const OCIO::ConstConfigRcPtr& c) {
    std::vector<std::string> out{"scene_linear"};
    for (int i = 0; i < c->getNumColorSpaces(OCIO::SEARCH_REFERENCE_SPACE_SCENE, OCIO::COLORSPACE_ACTIVE); ++i) {
        const char* name = c->getColorSpaceNameByIndex(OCIO::SEARCH_REFERENCE_SPACE_SCENE, OCIO::COLORSPACE_ACTIVE, i);
        OCIO::ConstColorSpaceRcPtr cs = c->getColorSpace(name);
        if (cs && !cs->isData() && cs->getEncoding() != std::string("sdr-video")) out.emplace_back(name);
    }
    return out;
}

void drawViewportSection(ViewSettings& v, Layout& layout) {
    sectionHeader("Viewport");
    int mode = v.pathTraceAtRest ? 1 : 0;
    if (ImGui::Combo("Render mode", &mode, "Fast\0Path traced at rest\0")) v.pathTraceAtRest = mode == 1;
    noteWidgetRect(layout, "Render mode");
    helpMarker(
        "Fast: the real-time renderer, always. Path traced at rest: the fast renderer while the camera or a "
        "parameter moves; once the view rests the viewport path-traces it at full resolution with the "
        "document's lights, as `fraktal render --mode path` does, adding samples every frame up to the cap. "
        "Any change returns to the fast renderer.");
    if (v.pathTraceAtRest)
        dragInt("Path spp cap", v.pathSppCap, 1, 65536, 1.0f,
                "Samples per pixel the path tracer accumulates at rest; then the viewport idles.");
    dragInt("Steps per frame", v.stepsPerFrame, 1, 1000, 0.5f,
            "March steps per ray per frame. Unfinished rays go on next frame: a smaller budget keeps the UI "
            "responsive on a CPU renderer.");
    dragDouble("Resolution", v.renderScale, 0.1, 1.0, 0.005f, "%.2f x",
               "Share of the window's pixels the viewport renders (upscaled for display).");
    dragDouble("Frame-time target", v.frameTimeTargetMs, 0.0, 1000.0, 0.5f, "%.0f ms",
               "While the camera or a parameter moves, the viewport renders fewer pixels to hold this frame time, "
               "then refines at full resolution when the view rests. 0: always full resolution.");
    dragDouble("Lowest motion scale", v.motionMinScale, 1.0 / 16.0, 1.0, 0.002f, "%.3f x",
               "The smallest share of each side the viewport goes down to under motion to hold the frame-time "
               "target (on a loaded machine it may need an eighth).");
    ImGui::Checkbox("Reprojection", &v.reprojection);
    helpMarker("Carry march distances over when the camera moves (seed 4.2). Off: every move restarts the rays.");
    dragInt("AA cap (spp)", v.aaCap, 1, 256, 0.1f,
            "Jittered samples per pixel accumulated while the camera rests; then the viewport idles.");
    dragInt("Cone pre-pass tile", v.coneTile, 0, 32, 0.1f,
            "A low-resolution cone march in tiles of this many pixels finds where full-resolution rays may start "
            "(0: off).");
    dragInt("Colour carry (frames)", v.maxCarryFrames, 0, 64, 0.1f,
            "Under motion a reprojected hit keeps the colour carried with its surface point for at most this many "
            "frames, then it is shaded again (specular and fog depend on the view). 0: shade every hit.");
    ImGui::Checkbox("Motion filter", &v.motionFilter);
    helpMarker(
        "Under motion, show each pixel as a reconstruction from the samples scattered around it "
        "(reprojected colours lie anywhere in their pixel) instead of its one sample.");
    if (v.motionFilter)
        dragDouble("Filter radius", v.motionFilterRadius, viewport::ViewportOptions::kMinFilterRadius,
                   viewport::ViewportOptions::kMaxFilterRadius, 0.01f, "%.2f px",
                   "The motion filter's reach. 1 px leaves samples at pixel centres as they are; wider is softer "
                   "and closer to the anti-aliased image the view settles to.");
    ImGui::Checkbox("Coarse hits", &v.coarseHits);
    helpMarker(
        "Under motion, a ray that keeps the colour carried to its pixel stops within two pixel footprints of the "
        "surface instead of marching on: about a quarter fewer DE evaluations, and thin parts look slightly "
        "thicker while the camera moves. At rest every ray marches on to the surface.");
}

void drawMarchSection(RenderSettings& r) {
    sectionHeader("Marching (viewport and export)");
    dragInt("Max steps per ray", r.maxSteps, 8, kMaxMarchSteps, 1.0f, "Sphere-tracing steps before a ray gives up.");
    dragDouble("Detail", r.detail, 0.01, 10.0, 0.005f, "%.3f px",
               "Hit threshold in pixel footprints: smaller is finer and slower.");
    dragDouble("Over-relaxation", r.overRelaxation, 1.0, 1.9, 0.005f, "%.2f",
               "Initial step factor of the over-relaxed marcher (1: plain sphere tracing).");
}

// The DE step factor: the check's (AutoStepFactor) after every structure change, or the user's.
void drawStepFactorSection(AutoStepFactor& a, Formula& f) {
    sectionHeader("DE step factor");
    if (ImGui::Checkbox("Set by hand", &a.overridden) && !a.overridden && a.measured > 0.0) f.deFactor = a.measured;
    helpMarker(
        "Off: the factor `fraktal check` measures for the formula is applied after every change of its "
        "structure, so the march never overshoots. On: the value below is kept.");
    ImGui::BeginDisabled(!a.overridden);
    dragDouble("Step factor", f.deFactor, kMinStepFactor, kMaxStepFactor, 0.005f, "%.3f",
               "Multiplies the distance estimate: smaller is safer and slower.");
    ImGui::EndDisabled();
    if (a.noHits)
        ImGui::TextDisabled("Not measured: no ray of the check met the object from this camera; the factor is kept.");
    else if (a.noSafeFactor)
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1),
                           "No safe factor: the estimate overshoots %.3g times the distance (jumps or dust); "
                           "marching at %.3f may still show specks.",
                           a.worst, f.deFactor);
    else if (a.measured > 0.0 && a.refining())
        ImGui::TextDisabled("Measured for this structure: %.3f on %d rays; sampling more for the rare worst ones...",
                            a.measured, a.rays);
    else if (a.measured > 0.0)
        ImGui::TextDisabled("Measured for this structure: %.3f on %d rays (%.2f s)", a.measured, a.rays, a.seconds);
    else
        ImGui::TextDisabled("The preset's own factor (measured after a structure change).");
    if (const int k = firstJumpingStep(f.nodes); k >= 0) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1),
                           "Step %d (%s) jumps (a non-integer power's cut, a pole, a wrap): the factor is measured "
                           "on sampled rays, not proven. Rare rays near the jump may overshoot: lower it by hand "
                           "if specks show.",
                           k + 1, std::string(f.nodes[size_t(k)].block->label).c_str());
        ImGui::PopTextWrapPos();
    }
}

void drawColourSection(EditorState& s, RenderSettings& r) {
    sectionHeader("Colour (OCIO)");
    if (!s.color) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "No OCIO config.");
        return;
    }
    const OCIO::ConstConfigRcPtr config = s.color->config();
    nameCombo("Working space", r.workingSpace, workingSpacesOf(config));
    helpMarker("Scene-linear space the image is rendered in (the EXR's space).");
    if (nameCombo("Display", r.display, displaysOf(config))) {
        const std::vector<std::string> views = viewsOf(config, r.display);
        if (!views.empty()) r.view = views.front();
    }
    nameCombo("View", r.view, viewsOf(config, r.display));
    helpMarker("The OCIO view: the viewport and the export's PNG go through the same display/view transform.");
    keyMarker(s, "colorManagement.exposure", {r.exposure});
    dragDouble("Exposure", r.exposure, -20.0, 20.0, 0.02f, "%+.2f EV",
               "Applied at display only, before the view transform: the rendered data stays linear.");
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("Config: %s", s.color->configPath().c_str());
    ImGui::PopTextWrapPos();
}

}  // namespace

void drawRenderTab(EditorState& s) {
    // Leave the labels room: they name what a preset field does.
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    if (s.doc.plane) {
        // A 2D document has no march; its view refines by itself (the View tab).
        drawColourSection(s, s.doc.plane->render);
    } else {
        drawViewportSection(s.doc.view, s.layout);
        drawMarchSection(s.doc.preset.render);
        drawStepFactorSection(s.stepFactor, s.doc.preset.formula);
        drawColourSection(s, s.doc.preset.render);
    }
    ImGui::PopItemWidth();
}

}  // namespace fraktal::editor
