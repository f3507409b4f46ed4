// Orbit and fly camera controls as pure functions of one frame's input, so the main loop only
// gathers input and the rules are testable without a window.
#pragma once

#include "app/editor/input/fly_speed.hpp"
#include "core/camera.hpp"

namespace fraktal::editor {

enum class CameraMode { Orbit, Fly };

// One frame of input over the viewport (already filtered: nothing here when ImGui wants it).
struct CameraInput {
    vec2 rotateDrag{0.0};  // pixels dragged with the left button (orbit) / mouse look (fly)
    vec2 panDrag{0.0};     // pixels dragged with the right or middle button
    double scroll = 0.0;   // wheel notches, positive = towards the target
    vec3 move{0.0};        // fly: x right (D-A), y up (E-Q), z forward (W-S)
    bool boost = false;    // Shift: 4x
    double dt = 0.0;       // seconds since the last frame
    double viewportHeight = 720.0;
};

struct CameraControls {
    CameraMode mode = CameraMode::Orbit;
    double degreesPerPixel = 0.25;
    FlyRule fly;
};

// Orbit: drag turns the eye about the target (pitch kept off the poles), pan moves both,
// scroll scales the distance to the target. Returns whether the camera changed.
bool orbitCamera(Camera& cam, const CameraInput& in, const CameraControls& c);
// Fly: mouse look turns the view about the eye; `move` translates eye and target together by
// flyStep() with the DE `de` (empty: the CPU DE, see EyeDistance for formulas without one).
// Returns whether the camera changed.
bool flyCamera(Camera& cam, const Formula& f, const CameraInput& in, const CameraControls& c,
               const DistanceAt& de = {});

}  // namespace fraktal::editor
