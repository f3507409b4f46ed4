// Gathers one frame of viewport camera input: drags from the window's mouse events
// (pointer_input.hpp), the wheel over the viewport, fly keys while the viewport has the keyboard.
#pragma once

#include "app/editor/input/camera_controller.hpp"
#include "app/editor/state/editor_state.hpp"

namespace fraktal::editor {

// Fills `in` from the frame's queued events (consuming them) and says whether a gesture (drag
// or fly key) is in progress.
bool gatherCameraInput(EditorState& s, CameraInput& in);

// Camera keys act only while the viewport is hovered or was clicked last, never while a text
// field has focus.
bool viewportHasKeyboard(const EditorState& s);

// Gathers input and moves the document's camera by the active controller.
void updateCamera(EditorState& s);

// "Frame object" (F): the camera outside the surface with the whole object in view, found from
// the DE (formula_fit.hpp).
void frameObject(EditorState& s);

// Ctrl+click (or a click while the Lights tab's "Pick focus" waits): sets the lens focus
// distance to the surface under window point `at` in the 3D viewport (one undo step), or says on
// the status line that the sky is there.
void pickFocusAt(EditorState& s, const vec2& at);

// The 2D document's navigation: a drag (any button) pans, the wheel zooms about the cursor.
// The image is imageWidth x imageHeight pixels shown over the viewport.
void updatePlaneView(EditorState& s, int imageWidth, int imageHeight);

}  // namespace fraktal::editor
