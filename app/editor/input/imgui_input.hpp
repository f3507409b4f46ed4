// The window's mouse, key and character events, handed out a frame at a time (to Dear ImGui and
// to the editor's own handlers alike), so that no click or key press is lost however long a frame
// takes and both see the events in the order they happened.
//
// Dear ImGui 1.86 (Debian's libimgui-dev) has no input event queue: each frame its GLFW backend
// polls where the cursor is and which buttons and keys are down. On a slow frame (a heavy preset
// on llvmpipe: 190-340 ms) a person's move onto a tab and click all land between two frames, and
// the frame that sees the press is the first to see the cursor there too. A tab (or any item that
// allows overlap) counts as hovered only when the previous frame hovered nothing else, so that
// press was dropped: 7-8 of 10 quick clicks on the Scene panel's tabs did nothing. A press and
// release within one frame, or a key tapped within one, are lost the same way.
//
// So the editor queues the events in the order GLFW delivers them, and each frame takes those that
// Dear ImGui can see in one poll: a run of cursor moves, or one change of the mouse buttons, never
// both, never two changes of a key ImGui reads (editing and navigation keys, modifiers, and the
// letters of Ctrl+A/C/V/X/Y/Z while Ctrl is down), and no change of a modifier after a key it
// modifies changed (Ctrl released before A would leave A alone); the rest waits for the next frame
// (the editor polls instead of waiting while any do). Characters keep their place among the keys,
// so a Backspace typed between two letters edits what it followed; a plain letter's own key state
// is no reason to wait (ImGui reads its character). What a frame took is the state ImGui's io is
// given after the backend's own poll, and the pointer events and key presses the editor's
// viewport, shortcuts and dialogs handle that frame (editor.cpp).
#pragma once

#include <array>
#include <deque>
#include <vector>

#include "app/editor/input/pointer_input.hpp"

namespace fraktal::editor {

struct InputEvent {
    enum class Kind { CursorMove, MouseButton, Key, Char };
    Kind kind = Kind::CursorMove;
    double x = 0.0, y = 0.0;  // CursorMove, MouseButton: the window position
    int code = 0;             // MouseButton: the button; Key: the GLFW key code; Char: the code point
    bool down = false;        // MouseButton, Key: pressed (true) or released
    int mods = 0;             // MouseButton, Key: GLFW_MOD_* bits
};

class InputQueue {
   public:
    static constexpr int kMouseButtons = 5;  // ImGuiMouseButton_COUNT
    static constexpr int kKeys = 512;        // ImGuiIO::KeysDown, indexed by GLFW key codes

    void push(const InputEvent& event) { pending_.push_back(event); }
    // Events not yet handed out: the editor keeps drawing frames while there are any.
    bool pending() const { return !pending_.empty(); }
    size_t pendingCount() const { return pending_.size(); }

    // Takes the events of the next frame from the front of the queue (see above).
    void takeFrame();

    // The state after the events taken so far, for ImGui's io.
    double cursorX() const { return cursorX_; }
    double cursorY() const { return cursorY_; }
    bool hasCursor() const { return hasCursor_; }
    bool mouseDown(int button) const { return mouseDown_[size_t(button)]; }
    bool keyDown(int key) const { return key >= 0 && key < kKeys && keysDown_[size_t(key)]; }
    // What the last takeFrame took: characters for ImGui, pointer events and key presses for the
    // editor's own handlers.
    const std::vector<unsigned>& chars() const { return chars_; }
    const std::vector<PointerEvent>& pointerEvents() const { return pointerEvents_; }
    const std::vector<KeyPress>& keyPresses() const { return keyPresses_; }

   private:
    // Whether ImGui 1.86 reads this key's state (a second change of it must wait a frame).
    bool imguiReads(int key) const;

    std::deque<InputEvent> pending_;
    double cursorX_ = 0.0, cursorY_ = 0.0;
    bool hasCursor_ = false;
    std::array<bool, kMouseButtons> mouseDown_{};
    std::array<bool, kKeys> keysDown_{};
    std::vector<unsigned> chars_;
    std::vector<PointerEvent> pointerEvents_;
    std::vector<KeyPress> keyPresses_;
};

}  // namespace fraktal::editor
