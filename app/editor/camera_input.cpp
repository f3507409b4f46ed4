#include "app/editor/camera_input.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/editor/plane_edits.hpp"

namespace fraktal::editor {

bool gatherCameraInput(const EditorState& s, CameraInput& in) {
    const ImGuiIO& io = ImGui::GetIO();
    const Layout& l = s.layout;
    const bool overViewport = io.MousePos.x >= l.viewportX && io.MousePos.x < l.viewportX + l.viewportW &&
                              io.MousePos.y >= l.viewportY && io.MousePos.y < l.viewportY + l.viewportH;
    // A drag belongs to the viewport when it started there and no ImGui window took it.
    const bool mouseFree = !io.WantCaptureMouse;
    in.dt = io.DeltaTime;
    in.viewportHeight = l.viewportH;
    bool gesture = false;
    if (mouseFree) {
        const vec2 delta(io.MouseDelta.x, io.MouseDelta.y);
        if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) in.rotateDrag = delta, gesture = true;
        if (ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle))
            in.panDrag = delta, gesture = true;
        if (overViewport) in.scroll = io.MouseWheel;
    }
    if (s.cameraControls.mode == CameraMode::Fly && !io.WantTextInput && !io.KeyCtrl) {
        auto down = [](int key) { return ImGui::IsKeyDown(key) ? 1.0 : 0.0; };
        in.move = vec3(down(GLFW_KEY_D) - down(GLFW_KEY_A), down(GLFW_KEY_E) - down(GLFW_KEY_Q),
                       down(GLFW_KEY_W) - down(GLFW_KEY_S));
        in.boost = io.KeyShift;
        if (in.move != vec3(0.0)) gesture = true;
    }
    return gesture;
}

void updatePlaneView(EditorState& s, int imageWidth, int imageHeight) {
    if (!s.doc.plane) return;
    const ImGuiIO& io = ImGui::GetIO();
    const Layout& l = s.layout;
    s.cameraGesture = false;
    if (io.WantCaptureMouse) return;  // over a panel, or a drag that a panel took
    PlaneInput in;
    in.cursorX = io.MousePos.x - l.viewportX;
    in.cursorY = io.MousePos.y - l.viewportY;
    const bool overViewport =
        in.cursorX >= 0 && in.cursorX < l.viewportW && in.cursorY >= 0 && in.cursorY < l.viewportH;
    for (int button = 0; button < 3; ++button) {
        if (!ImGui::IsMouseDown(button)) continue;
        s.cameraGesture = true;  // one undo step per drag
        // The frame the button goes down, the delta is the move before the press (frames are
        // slow while a pass renders): a drag starts counting from the next frame.
        if (!ImGui::IsMouseClicked(button)) {
            in.dragX = io.MouseDelta.x;
            in.dragY = io.MouseDelta.y;
        }
        break;
    }
    if (overViewport) in.wheel = io.MouseWheel;
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
}

}  // namespace fraktal::editor
