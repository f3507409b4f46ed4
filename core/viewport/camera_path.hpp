// Scripted camera paths for `fraktal bench viewport` and the tests: a preset's camera moved a
// little each frame, as a user's drag would.
#pragma once

#include <optional>
#include <string>

#include "core/camera.hpp"

namespace fraktal::viewport {

enum class CameraPath { Orbit, Dolly, Pan };

std::optional<CameraPath> parseCameraPath(const std::string& name);  // "orbit", "dolly", "pan"
const char* toString(CameraPath p);

// The camera of frame `frame` (0: `start` unchanged). Orbit: around the vertical axis through the
// target, `degreesPerFrame` per frame. Dolly: toward the target by 0.4 % of the distance per
// frame. Pan: the view direction turns about the camera's up axis by `degreesPerFrame` per frame.
Camera cameraOnPath(const Camera& start, CameraPath path, int frame, double degreesPerFrame = 0.5);

}  // namespace fraktal::viewport
