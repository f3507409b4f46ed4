// The Render tab: the viewport's budget (the document's ViewSettings), the march settings of the
// preset's `render` section, and its colour settings: working space, OCIO display and view and
// exposure; the renderer's own knobs under a closed Advanced header. The viewport and the still export read the same
// preset fields, so what the viewport shows is what the export writes.
#include <imgui.h>

#include <string>
#include <vector>

#include "app/editor/panels/panels.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/setting_widgets.hpp"
#include "app/editor/widgets/text_fit.hpp"
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
    } else {
        checkComboFits(label, value);
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
    const char* modes[] = {"Fast", "Path traced at rest"};
    if (ImGui::Combo("Render mode", &mode, modes, IM_ARRAYSIZE(modes))) v.pathTraceAtRest = mode == 1;
    checkComboFits("Render mode", modes[mode]);
    noteWidgetRect(layout, "Render mode");
    helpMarker(
        "Fast: the real-time renderer, always. Path traced at rest: the fast renderer while the camera or a "
        "parameter moves; once the view rests the viewport path-traces it at full resolution with the scene's "
        "lights (the Lights tab), as a path-traced export does, adding samples every frame up to the limit. "
        "Any change returns to the fast renderer.");
    if (v.pathTraceAtRest)
        dragInt("Samples at rest", v.pathSppCap, 1, 65536, 1.0f,
                "Samples per pixel the path tracer adds up while the view rests; then the viewport idles.");
    dragDouble("Resolution", v.renderScale, 0.1, 1.0, 0.005f, "%.2f x",
               "Share of the window's pixels the viewport renders (upscaled for display).");
    dragDouble("Frame-time target", v.frameTimeTargetMs, 0.0, 1000.0, 0.5f, "%.0f ms",
               "While the camera or a parameter moves, the viewport renders fewer pixels to hold this frame time, "
               "then refines at full resolution when the view rests. 0: always full resolution.");
    dragInt("Anti-aliasing", v.aaCap, 1, 256, 0.1f,
            "Samples per pixel added up while the camera rests, for smooth edges; then the viewport idles.");
}

// How the viewport keeps up while the view moves: knobs of the renderer itself, under a header
// that starts closed.
void drawAdvancedSection(ViewSettings& v, RenderSettings& r, Layout& layout) {
    ImGui::Spacing();
    const bool open = ImGui::CollapsingHeader("Advanced");
    noteWidgetRect(layout, "header:Advanced");
    if (!open) return;
    dragInt("Steps per frame", v.stepsPerFrame, 1, 1000, 0.5f,
            "How far each ray marches in one frame at most; unfinished rays go on in the next. While the view "
            "rests, a heavy fractal marches fewer steps a frame so that the editor stays responsive.");
    dragDouble("Lowest motion scale", v.motionMinScale, 1.0 / 16.0, 1.0, 0.002f, "%.3f x",
               "The smallest share of each side the viewport goes down to while the view moves, to hold the "
               "frame-time target (on a busy machine it may need an eighth).");
    ImGui::Checkbox("Reprojection", &v.reprojection);
    helpMarker(
        "Keep what the rays found when the camera moves, so that the image sharpens sooner. Off: every move "
        "starts the rays again.");
    dragInt("Cone pre-pass tile", v.coneTile, 0, 32, 0.1f,
            "A coarse first pass over tiles of this many pixels finds where the rays can start, which saves "
            "time on open scenes (0: off).");
    noteWidgetRect(layout, "Cone pre-pass tile");
    dragInt("Colour carry", v.maxCarryFrames, 0, 64, 0.1f,
            "While the view moves, a point of the surface keeps its colour for at most this many frames before it "
            "is shaded again (highlights and fog change with the view). 0: shade every frame.");
    ImGui::Checkbox("Motion filter", &v.motionFilter);
    helpMarker("While the view moves, smooth each pixel from the samples around it instead of showing its one sample.");
    if (v.motionFilter)
        dragDouble("Filter radius", v.motionFilterRadius, viewport::ViewportOptions::kMinFilterRadius,
                   viewport::ViewportOptions::kMaxFilterRadius, 0.01f, "%.2f px",
                   "How far the motion filter reaches. 1 px leaves the samples as they are; wider is softer and "
                   "closer to the image the view settles to.");
    ImGui::Checkbox("Coarse hits", &v.coarseHits);
    helpMarker(
        "While the view moves, rays stop a little short of the surface: about a quarter faster, and thin parts "
        "look slightly thicker until the camera rests.");
    dragDouble("Over-relaxation", r.overRelaxation, 1.0, 1.9, 0.005f, "%.2f",
               "How boldly rays stride towards the surface at first (1: cautious steps).");
    dragDouble("Step growth", r.maxStepGrowth, 1.0, kMaxStepGrowth, 0.05f, "%.1fx",
               "How far a ray may lengthen its steps where the distance estimate is cautious. Larger is faster on "
               "slow formulas; 1 keeps every step at the safe length.");
}

void drawMarchSection(RenderSettings& r) {
    sectionHeader("Detail (viewport and export)");
    dragDouble("Detail", r.detail, 0.01, 10.0, 0.005f, "%.3f px",
               "How close a ray comes to the surface before it stops, in pixels: smaller is finer and slower.");
    dragInt("Max steps per ray", r.maxSteps, 8, kMaxMarchSteps, 1.0f,
            "How many steps a ray takes before it gives up: raise it when far parts show holes.");
}

// The DE step factor: the check's (AutoStepFactor) after every structure change, or the user's.
void drawStepFactorSection(AutoStepFactor& a, Formula& f) {
    sectionHeader("Step size");
    if (ImGui::Checkbox("Set by hand", &a.overridden) && !a.overridden && a.measured > 0.0) f.deFactor = a.measured;
    helpMarker(
        "Off: after every change of the nodes the editor measures the largest step that never jumps through "
        "the surface and uses it. On: the value below is kept.");
    ImGui::BeginDisabled(!a.overridden);
    dragDouble("Step factor", f.deFactor, kMinStepFactor, kMaxStepFactor, 0.005f, "%.3f",
               "How far a ray steps towards the surface: smaller is safer (no specks or holes) and slower.");
    ImGui::EndDisabled();
    if (a.noHits)
        ImGui::TextDisabled("Not measured: from this camera no test ray met the object; the factor is kept.");
    else if (a.noSafeFactor)
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1),
                           "No safe factor: rays can jump %.3g times past the surface (jumps or dust); at "
                           "%.3f specks may still show.",
                           a.worst, f.deFactor);
    else if (a.measured > 0.0 && a.refining())
        ImGui::TextDisabled("Measured for these nodes: %.3f on %d rays; testing more for the rare worst ones...",
                            a.measured, a.rays);
    else if (a.measured > 0.0)
        ImGui::TextDisabled("Measured for these nodes: %.3f on %d rays (%.2f s)", a.measured, a.rays, a.seconds);
    else
        ImGui::TextDisabled("The preset's own factor (measured after a change of the nodes).");
    if (const int k = firstJumpingStep(f.nodes); k >= 0)
        ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1),
                           "Node %d (%s) has a seam where the shape jumps: the factor is measured on test rays, "
                           "not proven. Rays near the seam may jump past the surface: lower it by hand if specks "
                           "show.",
                           k + 1, std::string(f.nodes[size_t(k)].block->label).c_str());
}

void drawColourSection(EditorState& s, RenderSettings& r) {
    sectionHeader("Colour");
    if (!s.color) {
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "No OCIO config.");
        return;
    }
    const OCIO::ConstConfigRcPtr config = s.color->config();
    nameCombo("Working space", r.workingSpace, workingSpacesOf(config));
    helpMarker("The colour space the image is rendered and saved in (the EXR's).");
    if (nameCombo("Display", r.display, displaysOf(config))) {
        const std::vector<std::string> views = viewsOf(config, r.display);
        if (!views.empty()) r.view = views.front();
    }
    nameCombo("View", r.view, viewsOf(config, r.display));
    helpMarker("How the image is turned into the display's colours: the viewport and the exported PNG look the same.");
    keyMarker(s, "colorManagement.exposure", {r.exposure});
    dragDouble("Exposure", r.exposure, -20.0, 20.0, 0.02f, "%+.2f EV",
               "Applied at display only, before the view transform: the rendered data stays linear.");
    ImGui::TextDisabled("Colour configuration: %s", s.color->configPath().c_str());
}

}  // namespace

void drawRenderTab(EditorState& s) {
    // Leave the labels room, and wrap every line of text at the panel's edge.
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    ImGui::PushTextWrapPos(0.0f);
    if (s.doc.plane) {
        // A 2D document has no march; its view refines by itself (the View tab).
        drawColourSection(s, s.doc.plane->render);
    } else {
        drawViewportSection(s.doc.view, s.layout);
        drawMarchSection(s.doc.preset.render);
        drawStepFactorSection(s.stepFactor, s.doc.preset.formula);
        drawColourSection(s, s.doc.preset.render);
        drawAdvancedSection(s.doc.view, s.doc.preset.render, s.layout);
    }
    ImGui::PopTextWrapPos();
    ImGui::PopItemWidth();
}

}  // namespace fraktal::editor
