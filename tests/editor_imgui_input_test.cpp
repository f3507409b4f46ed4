// The queue that hands window events to Dear ImGui a frame at a time (app/editor/input/imgui_input.hpp):
// what one frame's poll can see is taken, the rest waits, nothing is dropped and the order stays.
#include <gtest/gtest.h>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "app/editor/input/imgui_input.hpp"
#include "app/editor/viewport/ui_redraw.hpp"

namespace fraktal::editor {
namespace {

using InputKind = InputEvent::Kind;

InputEvent move(double x, double y) { return {InputKind::CursorMove, x, y}; }
InputEvent button(int b, bool down) { return {InputKind::MouseButton, 0, 0, b, down}; }
InputEvent key(int k, bool down) { return {InputKind::Key, 0, 0, k, down}; }
InputEvent character(char c) { return {InputKind::Char, 0, 0, int(c), true}; }

// A quick tap on a tab (moves, press and release all between two frames): the frame that sees
// the cursor on the tab comes before the one that sees the press, and the release after that.
TEST(InputQueue, AMoveAndAClickBetweenTwoFramesTakeThreeFrames) {
    InputQueue q;
    for (const InputEvent& e : {move(10, 10), move(80, 560), button(0, true), button(0, false)}) q.push(e);
    q.takeFrame();
    EXPECT_EQ(q.cursorX(), 80);
    EXPECT_EQ(q.cursorY(), 560);
    EXPECT_FALSE(q.mouseDown(0));
    q.takeFrame();
    EXPECT_TRUE(q.mouseDown(0));
    EXPECT_TRUE(q.pending());
    q.takeFrame();
    EXPECT_FALSE(q.mouseDown(0));
    EXPECT_FALSE(q.pending());
    q.takeFrame();  // nothing left: the state stays
    EXPECT_EQ(q.cursorX(), 80);
    EXPECT_FALSE(q.mouseDown(0));
}

// A press, then a drag: the press is seen where it happened, the moves in the next frame.
TEST(InputQueue, APressIsSeenWhereItHappened) {
    InputQueue q;
    q.push(move(5, 5));
    q.takeFrame();
    for (const InputEvent& e : {button(0, true), move(50, 5), move(90, 5), button(0, false)}) q.push(e);
    q.takeFrame();
    EXPECT_TRUE(q.mouseDown(0));
    EXPECT_EQ(q.cursorX(), 5);
    q.takeFrame();
    EXPECT_TRUE(q.mouseDown(0));
    EXPECT_EQ(q.cursorX(), 90);
    q.takeFrame();
    EXPECT_FALSE(q.mouseDown(0));
    EXPECT_EQ(q.pendingCount(), 0u);
}

// Typing "ab", Backspace, "c" within one frame: every change of a key ImGui reads is seen, none
// twice in a frame, and each character arrives after the key changes queued before it.
TEST(InputQueue, KeysTappedWithinAFrameAreAllSeenInOrder) {
    InputQueue q;
    for (const InputEvent& e :
         {key(GLFW_KEY_A, true), character('a'), key(GLFW_KEY_A, false), key(GLFW_KEY_B, true), character('b'),
          key(GLFW_KEY_B, false), key(GLFW_KEY_BACKSPACE, true), key(GLFW_KEY_BACKSPACE, false), key(GLFW_KEY_C, true),
          character('c'), key(GLFW_KEY_C, false)})
        q.push(e);
    std::string typed;
    std::vector<std::string> backspaceFrames;
    int frames = 0;
    while (q.pending()) {
        q.takeFrame();
        ++frames;
        for (unsigned c : q.chars()) typed += char(c);
        if (q.keyDown(GLFW_KEY_BACKSPACE)) backspaceFrames.push_back(typed);
        ASSERT_LT(frames, 20);
    }
    EXPECT_EQ(typed, "abc");
    // Backspace was down in exactly one frame, after "ab" and before "c".
    ASSERT_EQ(backspaceFrames.size(), 1u);
    EXPECT_EQ(backspaceFrames[0], "ab");
    EXPECT_FALSE(q.keyDown(GLFW_KEY_C));
    // "ab" and Backspace's press, then its release with "c": a letter's own key state does not
    // hold the queue (ImGui reads its character), Backspace's second change does.
    EXPECT_EQ(frames, 2);
}

// Modifiers and keys held together go in one frame (Ctrl+S): a combination is not split.
TEST(InputQueue, ACombinationIsOneFrame) {
    InputQueue q;
    for (const InputEvent& e : {key(GLFW_KEY_LEFT_CONTROL, true), key(GLFW_KEY_S, true)}) q.push(e);
    q.takeFrame();
    EXPECT_TRUE(q.keyDown(GLFW_KEY_LEFT_CONTROL));
    EXPECT_TRUE(q.keyDown(GLFW_KEY_S));
    EXPECT_FALSE(q.pending());
}

// Every shortcut letter ImGui reads with Ctrl, released before or after Ctrl, and every way the
// four events can be split between the polls of successive frames (X hands them over as they
// arrive: Ctrl alone may reach one frame and the rest the next): some frame sees the letter down
// with Ctrl, which is what ImGui needs to see the shortcut.
TEST(InputQueue, ACtrlShortcutIsSeenHoweverItsEventsArriveAndInWhateverOrderTheyAreReleased) {
    for (const int letter : {GLFW_KEY_A, GLFW_KEY_C, GLFW_KEY_V, GLFW_KEY_X, GLFW_KEY_Y, GLFW_KEY_Z})
        for (const bool ctrlReleasedFirst : {false, true}) {
            std::vector<InputEvent> events{key(GLFW_KEY_LEFT_CONTROL, true), key(letter, true)};
            if (ctrlReleasedFirst)
                events.insert(events.end(), {key(GLFW_KEY_LEFT_CONTROL, false), key(letter, false)});
            else
                events.insert(events.end(), {key(letter, false), key(GLFW_KEY_LEFT_CONTROL, false)});
            // Which events arrive before each poll: bit i set, the poll after event i.
            for (unsigned splits = 0; splits < (1u << events.size()); ++splits) {
                InputQueue q;
                bool seen = false;
                for (size_t i = 0; i < events.size(); ++i) {
                    q.push(events[i]);
                    if (splits & (1u << i)) {
                        q.takeFrame();
                        seen |= q.keyDown(letter) && q.keyDown(GLFW_KEY_LEFT_CONTROL);
                    }
                }
                for (int frames = 0; q.pending() && frames < 10; ++frames) {
                    q.takeFrame();
                    seen |= q.keyDown(letter) && q.keyDown(GLFW_KEY_LEFT_CONTROL);
                }
                EXPECT_FALSE(q.pending());
                EXPECT_TRUE(seen) << "key " << letter << ", Ctrl released " << (ctrlReleasedFirst ? "first" : "last")
                                  << ", polls after events " << splits << ": no frame saw the shortcut";
                EXPECT_FALSE(q.keyDown(letter) || q.keyDown(GLFW_KEY_LEFT_CONTROL)) << "a key left down";
            }
        }
}

// During a camera gesture the window is drawn whole on its first frame (and kept), then from the
// copy for kUiRefreshFrames - 1 frames, then whole again; a resize or the gesture's end draws it
// whole at once, and a frame after the gesture never reuses the copy.
TEST(UiRedraw, AGestureReusesTheWindowBetweenWholeFrames) {
    UiRedrawState state;
    EXPECT_EQ(planUiDraw(state, false, 800, 600), UiDraw::Full);
    std::string plan;
    for (int frame = 0; frame < 2 * kUiRefreshFrames + 1; ++frame)
        plan += planUiDraw(state, true, 800, 600) == UiDraw::Cached ? 'c' : 'F';
    EXPECT_EQ(plan, "F" + std::string(kUiRefreshFrames - 1, 'c') + "F" + std::string(kUiRefreshFrames - 1, 'c') + "F");
    EXPECT_EQ(planUiDraw(state, true, 801, 600), UiDraw::FullAndCapture);  // resized
    EXPECT_EQ(planUiDraw(state, true, 801, 600), UiDraw::Cached);
    EXPECT_EQ(planUiDraw(state, false, 801, 600), UiDraw::Full);  // released
    EXPECT_EQ(planUiDraw(state, true, 801, 600), UiDraw::FullAndCapture);
    EXPECT_EQ(planUiDraw(state, true, 801, 600, false), UiDraw::Full);  // turned off
    EXPECT_EQ(planUiDraw(state, true, 801, 600), UiDraw::FullAndCapture);
}

}  // namespace
}  // namespace fraktal::editor
