// The viewport's input rules from window events (app/editor/input/pointer_input.hpp): clicks never
// move the camera, a drag counts only past its threshold and then in full, how events are split
// into frames changes nothing, and key taps shorter than a frame are kept.
#include <gtest/gtest.h>

#include "app/editor/input/pointer_input.hpp"

namespace fraktal::editor {
namespace {

using PointerKind = PointerEvent::Kind;
const ViewportRect kViewport{360, 20, 590, 780};

TEST(ViewportInput, ClickWithoutDragMovesNothing) {
    ViewportDrag drag;
    // The cursor comes from a panel far away, presses, wobbles 2 px, releases: one frame.
    const std::vector<PointerEvent> events = {{PointerKind::Move, 0, 100, 600},
                                              {PointerKind::Move, 0, 650, 400},
                                              {PointerKind::Press, 0, 650, 400},
                                              {PointerKind::Move, 0, 652, 401},
                                              {PointerKind::Release, 0, 652, 401}};
    const DragMotion m = consumePointerEvents(drag, events, kViewport, false);
    EXPECT_EQ(m.rotate, vec2(0.0));
    EXPECT_EQ(m.pan, vec2(0.0));
    EXPECT_TRUE(m.held);
    EXPECT_EQ(drag.button, -1);
    EXPECT_TRUE(drag.focused);
}

TEST(ViewportInput, DragIsTheSameWhateverTheFrameSplit) {
    std::vector<PointerEvent> events = {{PointerKind::Press, 1, 600, 300}};
    for (int i = 1; i <= 10; ++i) events.push_back({PointerKind::Move, 0, 600.0 + 7 * i, 300.0 - 3 * i});
    events.push_back({PointerKind::Release, 1, 670, 270});
    ViewportDrag oneFrame;
    const DragMotion all = consumePointerEvents(oneFrame, events, kViewport, false);
    EXPECT_EQ(all.pan, vec2(70, -30));  // all of it, from the press point
    EXPECT_EQ(all.rotate, vec2(0.0));
    ViewportDrag perEvent;
    vec2 sum(0.0);
    for (const PointerEvent& e : events) sum += consumePointerEvents(perEvent, {e}, kViewport, false).pan;
    EXPECT_EQ(sum, all.pan);
}

TEST(ViewportInput, PressOnAPanelOrOutsideStartsNoDrag) {
    ViewportDrag drag;
    DragMotion m = consumePointerEvents(drag, {{PointerKind::Press, 0, 650, 400}, {PointerKind::Move, 0, 750, 400}}, kViewport, true);
    EXPECT_EQ(m.rotate, vec2(0.0));
    EXPECT_FALSE(drag.focused);
    drag = {};
    m = consumePointerEvents(drag, {{PointerKind::Press, 0, 100, 400}, {PointerKind::Move, 0, 750, 400}}, kViewport, false);
    EXPECT_EQ(m.rotate, vec2(0.0));
    EXPECT_FALSE(m.held);
}

TEST(ViewportInput, KeyTapShorterThanAFrameStillMoves) {
    FlyKeys keys;
    flyKeyEvent(keys, FlyForward, true, 10.0);
    flyKeyEvent(keys, FlyForward, false, 10.0);  // press and release in one event poll
    auto seconds = takeFlyKeySeconds(keys, 10.5, true);
    EXPECT_DOUBLE_EQ(seconds[FlyForward], keys.minTapSeconds);
    vec3 dir;
    double duration = 0.0;
    flyMotion(seconds, dir, duration);
    EXPECT_GT(dir.z, 0.0);
    EXPECT_DOUBLE_EQ(duration, keys.minTapSeconds);
    // Held across frames: each frame gets its own share.
    flyKeyEvent(keys, FlyLeft, true, 11.0);
    EXPECT_DOUBLE_EQ(takeFlyKeySeconds(keys, 11.25, true)[FlyLeft], 0.25);
    EXPECT_DOUBLE_EQ(takeFlyKeySeconds(keys, 11.5, true)[FlyLeft], 0.25);
    // While a text field has the keys, nothing moves, and nothing is kept for later.
    EXPECT_DOUBLE_EQ(takeFlyKeySeconds(keys, 12.0, false)[FlyLeft], 0.0);
    flyKeyEvent(keys, FlyLeft, false, 12.0);
    EXPECT_DOUBLE_EQ(takeFlyKeySeconds(keys, 12.1, true)[FlyLeft], keys.minTapSeconds);
}

}  // namespace
}  // namespace fraktal::editor
