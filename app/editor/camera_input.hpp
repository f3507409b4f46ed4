// Gathers one frame of viewport camera input from ImGui's IO (mouse over the viewport and not
// captured by a panel; fly keys when no text field has focus).
#pragma once

#include "app/editor/camera_controller.hpp"
#include "app/editor/editor_state.hpp"

namespace fraktal::editor {

// Fills `in` and says whether a gesture (drag or fly key) is in progress.
bool gatherCameraInput(const EditorState& s, CameraInput& in);

// Gathers input and moves the document's camera by the active controller.
void updateCamera(EditorState& s);

// The 2D document's navigation: a drag (any button) pans, the wheel zooms about the cursor.
// The image is imageWidth x imageHeight pixels shown over the viewport.
void updatePlaneView(EditorState& s, int imageWidth, int imageHeight);

}  // namespace fraktal::editor
