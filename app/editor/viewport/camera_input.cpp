#include "app/editor/viewport/camera_input.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/editor/document/lights_edits.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/state/plane_edits.hpp"
#include "core/scene/formula_fit.hpp"

namespace fraktal::editor {

namespace {

ViewportRect viewportRect(const Layout& l) { return {l.viewportX, l.viewportY, l.viewportW, l.viewportH}; }

// The frame's viewport drag from the queued mouse events; a press that a panel or popup took
// (ImGui owns the mouse this frame) starts none.
DragMotion takeDrag(EditorState& s) {
    const DragMotion m =
        consumePointerEvents(s.drag, s.pointerEvents, viewportRect(s.layout), ImGui::GetIO().WantCaptureMouse);
    s.pointerEvents.clear();
    return m;
}

bool cursorOverViewport(const EditorState& s) {
    const ImGuiIO& io = ImGui::GetIO();
    return !io.WantCaptureMouse && viewportRect(s.layout).contains(io.MousePos.x, io.MousePos.y);
}

}  // namespace

bool viewportHasKeyboard(const EditorState& s) {
    return !ImGui::GetIO().WantTextInput && (cursorOverViewport(s) || s.drag.focused);
}

bool gatherCameraInput(EditorState& s, CameraInput& in) {
    const ImGuiIO& io = ImGui::GetIO();
    in.dt = io.DeltaTime;
    in.viewportHeight = s.layout.viewportH;
    const DragMotion drag = takeDrag(s);
    s.viewportClicks = drag.clicks;
    in.rotateDrag = drag.rotate;
    in.panDrag = drag.pan;
    if (cursorOverViewport(s)) in.scroll = io.MouseWheel;
    const bool fly = s.cameraControls.mode == CameraMode::Fly;
    const auto seconds = takeFlyKeySeconds(s.flyKeys, s.now, fly && viewportHasKeyboard(s));
    double duration = 0.0;
    flyMotion(seconds, in.move, duration);
    if (in.move != vec3(0.0)) in.dt = duration;
    in.boost = io.KeyShift;
    return drag.held || in.move != vec3(0.0);
}

void updatePlaneView(EditorState& s, int imageWidth, int imageHeight) {
    if (!s.doc.plane) return;
    const ImGuiIO& io = ImGui::GetIO();
    const Layout& l = s.layout;
    const DragMotion drag = takeDrag(s);
    s.cameraGesture = drag.held;  // one undo step per drag
    PlaneInput in;
    in.cursorX = io.MousePos.x - l.viewportX;
    in.cursorY = io.MousePos.y - l.viewportY;
    // Any button pans the 2D view.
    in.dragX = drag.rotate.x + drag.pan.x;
    in.dragY = drag.rotate.y + drag.pan.y;
    if (cursorOverViewport(s)) in.wheel = io.MouseWheel;
    s.doc.plane->view = navigatePlane(s.doc.plane->view, in, imageWidth, imageHeight, l.viewportW);
}

void updateCamera(EditorState& s) {
    CameraInput in;
    s.cameraGesture = gatherCameraInput(s, in);
    Camera& cam = s.doc.preset.camera;
    if (s.cameraControls.mode == CameraMode::Orbit) {
        orbitCamera(cam, in, s.cameraControls);
    } else {
        // In fly mode the left drag looks around; pan and wheel still work as in orbit.
        const Formula& formula = s.doc.preset.formula;
        flyCamera(cam, formula, in, s.cameraControls, s.eyeDistance.of(formula));
        CameraInput rest;
        rest.panDrag = in.panDrag;
        rest.scroll = in.scroll;
        rest.viewportHeight = in.viewportHeight;
        orbitCamera(cam, rest, s.cameraControls);
    }
    // Ctrl+click, or a click after the Lights tab's "Pick focus": the lens focuses there.
    for (const ViewportClick& c : s.viewportClicks)
        if (c.button == 0 && ((c.mods & GLFW_MOD_CONTROL) || s.lights.pickFocus)) pickFocusAt(s, c.at);
    s.viewportClicks.clear();
}

void frameObject(EditorState& s) {
    Camera& cam = s.doc.preset.camera;
    const Formula& f = s.doc.preset.formula;
    // Custom GLSL has no CPU body, and a GL probe per march step would stall the frame: the
    // bound sphere frames it.
    cam = f.cpuEvaluable() ? framedCamera(f, cpuDistance(f), cam) : defaultViewFor(f, cam);
}

void pickFocusAt(EditorState& s, const vec2& at) {
    const Layout& l = s.layout;
    LightsPanel& p = s.lights;
    p.pickFocus = false;
    ThinLens& lens = s.doc.preset.lighting.lens;
    if (!lens.enabled()) {
        setStatus(s, "Focus not set: depth of field is off (Lights tab: set an aperture radius first).", true);
        return;
    }
    const Preset& preset = s.doc.preset;
    const double ndcX = 2.0 * (at.x - l.viewportX) / std::max(double(l.viewportW), 1.0) - 1.0;
    const double ndcY = 1.0 - 2.0 * (at.y - l.viewportY) / std::max(double(l.viewportH), 1.0);
    const double aspect = double(l.viewportW) / std::max(double(l.viewportH), 1.0);
    const double imageHeight = l.viewportH * s.doc.view.renderScale;
    const std::optional<vec3> hit =
        surfaceUnderCursor(preset.formula, preset.camera, preset.render, preset.shading,
                           s.eyeDistance.of(preset.formula), ndcX, ndcY, aspect, imageHeight);
    if (!hit) {
        p.message = "Focus not changed: no surface under the cursor (sky).";
        p.messageIsError = false;
        setStatus(s, p.message, false);
        return;
    }
    lens.focusDistance = viewAxisDistance(preset.camera, *hit);
    char text[96];
    std::snprintf(text, sizeof text, "Focus distance %.4g (the surface under the cursor).", lens.focusDistance);
    p.message = text;
    p.messageIsError = false;
    setStatus(s, text, false);
}

}  // namespace fraktal::editor
