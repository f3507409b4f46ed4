// Viewport input from the window's own events (GLFW callbacks), not from per-frame polling: the
// events of a frame are queued with the cursor position or time they happened at, and the frame
// turns them into camera motion. So a slow frame changes nothing about where a drag ends, a click
// (press and release within a few pixels) never moves the camera, and a key tap shorter than a
// frame still moves the fly camera for as long as the key was down.
#pragma once

#include <array>
#include <vector>

#include "core/vec.hpp"

namespace fraktal::editor {

struct PointerEvent {
    enum class Kind { Move, Press, Release } kind = Kind::Move;
    int button = 0;           // 0 left, 1 right, 2 middle (GLFW's numbering)
    double x = 0.0, y = 0.0;  // window coordinates at the event
    int mods = 0;             // GLFW_MOD_* bits held at a press or release
};

// A viewport drag: the press must land on the viewport (not a panel); the motion counts only once
// the cursor has left a small circle around the press point (then all of it, so the scene follows
// the cursor).
struct ViewportDrag {
    double thresholdPixels = 4.0;
    int button = -1;  // the button held since a press on the viewport; -1: none
    vec2 pressAt{0.0}, last{0.0};
    bool dragging = false;  // the cursor has left the threshold circle
    bool focused = false;   // the last press landed on the viewport: it has the keyboard
    int pressMods = 0;      // modifiers held at the press
};

// A press and release on the viewport that never left the threshold circle.
struct ViewportClick {
    int button = 0;
    vec2 at{0.0};  // window coordinates of the press
    int mods = 0;  // GLFW_MOD_* bits held at the press
};

struct ViewportRect {
    double x = 0, y = 0, w = 0, h = 0;
    bool contains(double px, double py) const { return px >= x && px < x + w && py >= y && py < y + h; }
};

// One frame's worth of viewport motion from the queued events.
struct DragMotion {
    vec2 rotate{0.0};                   // left button, pixels
    vec2 pan{0.0};                      // right or middle button, pixels
    bool held = false;                  // a viewport button is (or was, this frame) down: one gesture
    std::vector<ViewportClick> clicks;  // clicks that ended this frame, in order
};

// Consumes `events` (in order). A press starts a drag when it lands inside `viewport` and
// `uiOwnsMouse` is false (no panel or popup took it this frame).
DragMotion consumePointerEvents(ViewportDrag& drag, const std::vector<PointerEvent>& events,
                                const ViewportRect& viewport, bool uiOwnsMouse);

// A key press (not a repeat) from the window's key events, with its GLFW_MOD_* bits.
struct KeyPress {
    int key = 0;
    int mods = 0;
};

// Fly keys from key events. GLFW gives no event times, so a key's time is when the frame's event
// poll saw it: a press released within the same poll (a tap shorter than a frame) counts as
// `minTapSeconds` rather than nothing.
enum FlyKey { FlyRight, FlyLeft, FlyUp, FlyDown, FlyForward, FlyBack, kFlyKeys };
struct FlyKeys {
    double minTapSeconds = 1.0 / 30.0;
    std::array<bool, kFlyKeys> down{};
    std::array<double, kFlyKeys> downSince{};    // press time, or the last take while held
    std::array<double, kFlyKeys> heldSeconds{};  // down time not yet taken
};
void flyKeyEvent(FlyKeys& keys, FlyKey key, bool pressed, double time);
// Seconds each key was down since the last take, up to `now`. When `accept` is false (a text
// field has the keys, or the viewport has neither hover nor focus) they are dropped: nothing moves.
std::array<double, kFlyKeys> takeFlyKeySeconds(FlyKeys& keys, double now, bool accept);
// The fly direction (x right, y up, z forward) and how long to move along it: the longest
// axis time (a tap of 20 ms moves 20 ms worth, whatever the frame time).
void flyMotion(const std::array<double, kFlyKeys>& seconds, vec3& direction, double& duration);

}  // namespace fraktal::editor
