// Keyboard shortcuts, as listed in the menus. ImGui 1.86 indexes keys by the GLFW key codes.
#include <GLFW/glfw3.h>
#include <imgui.h>

#include "app/editor/actions.hpp"
#include "app/editor/formula_edits.hpp"
#include "app/editor/node_list_edits.hpp"
#include "app/editor/panels.hpp"
#include "app/editor/plane_edits.hpp"

namespace fraktal::editor {

namespace {

bool pressed(int key) { return ImGui::IsKeyPressed(key, false); }

// A 2D document: Home resets the view; Ctrl+D and Delete act on the selected node's list.
void handlePlaneShortcuts(EditorState& s) {
    if (ImGui::GetIO().WantCaptureKeyboard && ImGui::IsAnyItemActive()) return;
    if (pressed(GLFW_KEY_HOME)) resetPlaneView(s);
    std::vector<PlaneNode>* list = planeList(s.doc.plane->formula, s.planeSelection.list);
    if (!list) return;
    if (ImGui::GetIO().KeyCtrl && pressed(GLFW_KEY_D) && duplicateNodeAt(*list, s.planeSelection.index))
        ++s.planeSelection.index;
    if (pressed(GLFW_KEY_DELETE)) removeNodeAt(*list, s.planeSelection.index);
    s.planeSelection = clampedSelection(s.doc.plane->formula, s.planeSelection);
}

}  // namespace

void handleShortcuts(EditorState& s) {
    const ImGuiIO& io = ImGui::GetIO();
    const bool ctrl = io.KeyCtrl, shift = io.KeyShift;
    // Undo/redo also while typing would fight the text field's own undo: only when not typing.
    if (!io.WantTextInput) {
        if (ctrl && pressed(GLFW_KEY_Z)) shift ? redo(s) : undo(s);
        if (ctrl && pressed(GLFW_KEY_Y)) redo(s);
    }
    if (ctrl && pressed(GLFW_KEY_S)) {
        if (shift) {
            s.dialogs.pathInput = s.file.path.string();
            s.dialogs.saveAs = true;
        } else {
            saveDocument(s);
        }
    }
    if (ctrl && pressed(GLFW_KEY_O)) s.dialogs.openPath = true;
    if (ctrl && pressed(GLFW_KEY_N)) requestAction(s, {shift ? PendingKind::NewPlane : PendingKind::New, {}});
    if (ctrl && pressed(GLFW_KEY_Q)) requestAction(s, {PendingKind::Quit, {}});
    if (pressed(GLFW_KEY_F12)) s.dialogs.exportStill = true;
    if (pressed(GLFW_KEY_F2)) s.panels.formula = !s.panels.formula;
    if (pressed(GLFW_KEY_F3)) s.panels.sidebar = !s.panels.sidebar;
    if (pressed(GLFW_KEY_F4)) s.panels.stats = !s.panels.stats;
    if (io.WantTextInput) return;
    if (s.doc.plane) {
        handlePlaneShortcuts(s);
        return;
    }
    Formula& f = s.doc.preset.formula;
    if (!io.WantCaptureKeyboard || !ImGui::IsAnyItemActive()) {
        if (pressed(GLFW_KEY_TAB) && !ctrl)
            s.cameraControls.mode = s.cameraControls.mode == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly;
        if (pressed(GLFW_KEY_HOME)) s.doc.preset.camera = defaultViewFor(f, s.doc.preset.camera);
        for (int i = 0; i < kViewSlots; ++i) {
            if (!pressed(GLFW_KEY_1 + i)) continue;
            auto& slot = s.doc.viewSlots[size_t(i)];
            if (ctrl)
                slot = s.doc.preset.camera;
            else if (slot)
                s.doc.preset.camera = *slot;
        }
        if (ctrl && pressed(GLFW_KEY_D) && duplicateNode(f, s.selectedNode)) ++s.selectedNode;
        if (pressed(GLFW_KEY_DELETE) && removeNode(f, s.selectedNode))
            s.selectedNode = std::clamp(s.selectedNode, 0, int(f.nodes.size()));
    }
}

}  // namespace fraktal::editor
