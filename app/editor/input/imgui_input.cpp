#include "app/editor/input/imgui_input.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>

namespace fraktal::editor {

namespace {

bool isModifier(int key) {
    switch (key) {
        case GLFW_KEY_LEFT_CONTROL:
        case GLFW_KEY_RIGHT_CONTROL:
        case GLFW_KEY_LEFT_SHIFT:
        case GLFW_KEY_RIGHT_SHIFT:
        case GLFW_KEY_LEFT_ALT:
        case GLFW_KEY_RIGHT_ALT:
        case GLFW_KEY_LEFT_SUPER:
        case GLFW_KEY_RIGHT_SUPER: return true;
        default: return false;
    }
}

}  // namespace

bool InputQueue::imguiReads(int key) const {
    switch (key) {
        // The keys the GLFW backend maps into io.KeyMap, and the modifiers.
        case GLFW_KEY_TAB:
        case GLFW_KEY_LEFT:
        case GLFW_KEY_RIGHT:
        case GLFW_KEY_UP:
        case GLFW_KEY_DOWN:
        case GLFW_KEY_PAGE_UP:
        case GLFW_KEY_PAGE_DOWN:
        case GLFW_KEY_HOME:
        case GLFW_KEY_END:
        case GLFW_KEY_INSERT:
        case GLFW_KEY_DELETE:
        case GLFW_KEY_BACKSPACE:
        case GLFW_KEY_SPACE:
        case GLFW_KEY_ENTER:
        case GLFW_KEY_ESCAPE:
        case GLFW_KEY_KP_ENTER: return true;
        // Select all, copy, paste, cut, redo, undo: read with Ctrl (or Super) held.
        case GLFW_KEY_A:
        case GLFW_KEY_C:
        case GLFW_KEY_V:
        case GLFW_KEY_X:
        case GLFW_KEY_Y:
        case GLFW_KEY_Z:
            return keyDown(GLFW_KEY_LEFT_CONTROL) || keyDown(GLFW_KEY_RIGHT_CONTROL) || keyDown(GLFW_KEY_LEFT_SUPER) ||
                   keyDown(GLFW_KEY_RIGHT_SUPER);
        default: return isModifier(key);
    }
}

void InputQueue::takeFrame() {
    chars_.clear();
    pointerEvents_.clear();
    keyPresses_.clear();
    bool moved = false, mouseChanged = false;
    std::vector<int> keysChanged;
    while (!pending_.empty()) {
        const InputEvent& e = pending_.front();
        switch (e.kind) {
            case InputEvent::Kind::CursorMove:
                // A move after a button change would move the press or release away from where
                // it happened.
                if (mouseChanged) return;
                cursorX_ = e.x;
                cursorY_ = e.y;
                hasCursor_ = true;
                moved = true;
                pointerEvents_.push_back({PointerEvent::Kind::Move, 0, e.x, e.y, 0});
                break;
            case InputEvent::Kind::MouseButton:
                // After a move, the place must be hovered for a frame before the press counts;
                // a second change of the buttons in one poll would hide the first.
                if (moved || mouseChanged) return;
                if (e.code >= 0 && e.code < kMouseButtons) mouseDown_[size_t(e.code)] = e.down;
                mouseChanged = true;
                pointerEvents_.push_back(
                    {e.down ? PointerEvent::Kind::Press : PointerEvent::Kind::Release, e.code, e.x, e.y, e.mods});
                break;
            case InputEvent::Kind::Key:
                // ImGui sees the keys as they are at the end of the poll, so a combination must
                // end a frame whole. A key read this frame waits for the next however the
                // modifiers changed since, and a modifier waits once a key it modifies changed:
                // xdotool and some keyboards release Ctrl before A, and Ctrl+A would otherwise
                // be A alone or no press at all.
                if (std::find(keysChanged.begin(), keysChanged.end(), e.code) != keysChanged.end()) return;
                if (isModifier(e.code) &&
                    std::any_of(keysChanged.begin(), keysChanged.end(), [](int k) { return !isModifier(k); }))
                    return;
                if (imguiReads(e.code)) keysChanged.push_back(e.code);
                if (e.code >= 0 && e.code < kKeys) keysDown_[size_t(e.code)] = e.down;
                if (e.down) keyPresses_.push_back({e.code, e.mods});
                break;
            case InputEvent::Kind::Char: chars_.push_back(unsigned(e.code)); break;
        }
        pending_.pop_front();
    }
}

}  // namespace fraktal::editor
