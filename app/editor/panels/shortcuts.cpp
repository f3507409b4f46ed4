// Keyboard shortcuts, as listed in the menus and the F1 help. They read the frame's key presses
// from the window's key events (EditorState::keyPresses), so a tap shorter than a frame, pressed
// and released within one event poll, is not lost.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_internal.h>  // the popup stack, ClosePopupToLevel

#include <algorithm>
#include <vector>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/node_list_edits.hpp"
#include "app/editor/input/popup_escape.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/state/plane_edits.hpp"
#include "app/editor/viewport/camera_input.hpp"
#include "core/scene/formula_fit.hpp"

namespace fraktal::editor {

namespace {

// A press of `key` this frame, with exactly the Ctrl and Shift state asked for.
struct Keys {
    const std::vector<KeyPress>& presses;
    bool operator()(int key, bool ctrl = false, bool shift = false) const {
        return std::any_of(presses.begin(), presses.end(), [&](const KeyPress& p) {
            return p.key == key && ((p.mods & GLFW_MOD_CONTROL) != 0) == ctrl &&
                   ((p.mods & GLFW_MOD_SHIFT) != 0) == shift;
        });
    }
};

// A 2D document: Home resets the view; Ctrl+D and Delete act on the selected node's list.
void handlePlaneShortcuts(EditorState& s, const Keys& pressed) {
    if (ImGui::GetIO().WantCaptureKeyboard && ImGui::IsAnyItemActive()) return;
    if (pressed(GLFW_KEY_HOME)) resetPlaneView(s);
    std::vector<PlaneNode>* list = planeList(s.doc.plane->formula, s.planeSelection.list);
    if (!list) return;
    if (pressed(GLFW_KEY_D, true) && duplicateNodeAt(*list, s.planeSelection.index)) ++s.planeSelection.index;
    if (pressed(GLFW_KEY_DELETE)) removeNodeAt(*list, s.planeSelection.index);
    s.planeSelection = clampedSelection(s.doc.plane->formula, s.planeSelection);
}

// Escape closes the menu or popup in front (popup_escape.hpp). Run before the frame's windows,
// so the popup is not drawn this frame and the next click reaches what lies under it. The press
// is then used up: a dialog under a closed combo must not take it as its Cancel too.
void closePopupOnEscape(std::vector<KeyPress>& presses) {
    const auto escape = [](const KeyPress& p) { return p.key == GLFW_KEY_ESCAPE; };
    if (std::none_of(presses.begin(), presses.end(), escape)) return;
    const ImVector<ImGuiPopupData>& stack = ImGui::GetCurrentContext()->OpenPopupStack;
    std::vector<bool> modal;
    // A popup opened this frame has no window yet: left open, as a modal would be.
    for (const ImGuiPopupData& p : stack) modal.push_back(!p.Window || (p.Window->Flags & ImGuiWindowFlags_Modal));
    const int left = popupsLeftOpenByEscape(modal, ImGui::IsAnyItemActive());
    if (left == stack.Size) return;
    ImGui::ClosePopupToLevel(left, true);
    std::erase_if(presses, escape);
}

}  // namespace

void handleShortcuts(EditorState& s) {
    closePopupOnEscape(s.keyPresses);
    const ImGuiIO& io = ImGui::GetIO();
    const Keys pressed{s.keyPresses};
    // Undo/redo also while typing would fight the text field's own undo: only when not typing.
    if (!io.WantTextInput) {
        if (pressed(GLFW_KEY_Z, true)) undo(s);
        if (pressed(GLFW_KEY_Z, true, true) || pressed(GLFW_KEY_Y, true)) redo(s);
    }
    if (pressed(GLFW_KEY_S, true)) saveDocument(s);
    if (pressed(GLFW_KEY_S, true, true)) {
        s.dialogs.pathInput = s.file.path.string();
        s.dialogs.saveAs = true;
    }
    if (pressed(GLFW_KEY_O, true)) s.dialogs.openPath = true;
    if (pressed(GLFW_KEY_N, true)) requestAction(s, {PendingKind::New, {}});
    if (pressed(GLFW_KEY_N, true, true)) requestAction(s, {PendingKind::NewPlane, {}});
    if (pressed(GLFW_KEY_Q, true)) requestAction(s, {PendingKind::Quit, {}});
    if (pressed(GLFW_KEY_F12)) s.dialogs.exportStill = true;
    if (pressed(GLFW_KEY_F1)) s.panels.help = !s.panels.help;
    if (pressed(GLFW_KEY_F2) && (s.panels.formula = !s.panels.formula)) s.panels.collapsed = false;
    if (pressed(GLFW_KEY_F3) && (s.panels.sidebar = !s.panels.sidebar)) s.panels.collapsed = false;
    if (pressed(GLFW_KEY_BACKSLASH, true)) s.panels.collapsed = !s.panels.collapsed;
    if (pressed(GLFW_KEY_F4)) s.panels.stats = !s.panels.stats;
    if (io.WantTextInput) return;
    if (s.doc.plane) {
        handlePlaneShortcuts(s, pressed);
        return;
    }
    Formula& f = s.doc.preset.formula;
    // Camera keys: only while the viewport is hovered or was clicked last (Tab stays ImGui's
    // focus navigation).
    if (viewportHasKeyboard(s)) {
        if (pressed(GLFW_KEY_V))
            s.cameraControls.mode = s.cameraControls.mode == CameraMode::Fly ? CameraMode::Orbit : CameraMode::Fly;
        if (pressed(GLFW_KEY_HOME)) s.doc.preset.camera = defaultViewFor(f, s.doc.preset.camera);
        if (pressed(GLFW_KEY_F)) frameObject(s);
        for (int i = 0; i < kViewSlots; ++i) {
            auto& slot = s.doc.viewSlots[size_t(i)];
            if (pressed(GLFW_KEY_1 + i, true))
                slot = s.doc.preset.camera;
            else if (pressed(GLFW_KEY_1 + i) && slot)
                s.doc.preset.camera = *slot;
        }
    }
    if (!io.WantCaptureKeyboard || !ImGui::IsAnyItemActive()) {
        if (pressed(GLFW_KEY_D, true) && duplicateNode(s.doc.preset, s.selectedNode)) ++s.selectedNode;
        if (pressed(GLFW_KEY_DELETE) && removeNode(s.doc.preset, s.selectedNode)) {
            s.selectedNode = std::clamp(s.selectedNode, 0, int(f.nodes.size()));
            fitFormulaAfterEdit(s.doc.preset);
        }
    }
}

}  // namespace fraktal::editor
