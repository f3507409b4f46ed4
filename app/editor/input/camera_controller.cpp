#include "app/editor/input/camera_controller.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace fraktal::editor {

namespace {

// Rotates v about `axis` (unit) by `degrees`.
vec3 rotateAbout(const vec3& v, const vec3& axis, double degrees) {
    return vec3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis) * glm::dvec4(v, 0.0));
}

// Turns `dir` by yaw about `up` and pitch about the right axis, never closer than ~1 degree to
// the poles (where lookAt degenerates).
vec3 turn(const vec3& dir, const vec3& up, double yawDeg, double pitchDeg) {
    const vec3 u = normalize(up);
    vec3 d = rotateAbout(dir, u, yawDeg);
    const double len = length(d);
    const double elevation = glm::degrees(std::asin(std::clamp(dot(d / len, u), -1.0, 1.0)));
    const double newElevation = std::clamp(elevation + pitchDeg, -89.0, 89.0);
    const vec3 right = normalize(glm::cross(d, u));
    return rotateAbout(d, right, newElevation - elevation);
}

}  // namespace

bool orbitCamera(Camera& cam, const CameraInput& in, const CameraControls& c) {
    bool changed = false;
    vec3 offset = cam.position - cam.target;
    if (in.rotateDrag != vec2(0.0)) {
        // Dragging right swings the eye left around the target, like turning the object.
        offset = turn(offset, cam.up, -in.rotateDrag.x * c.degreesPerPixel, in.rotateDrag.y * c.degreesPerPixel);
        changed = true;
    }
    if (in.scroll != 0.0) {
        offset *= std::pow(0.85, in.scroll);
        changed = true;
    }
    // Only a turn or a zoom moves the eye: target + (position - target) is not position in
    // floating point (0.9 comes back as 0.8999999999999999), and a frame without input must leave
    // the camera, and so the document, as it was.
    if (changed) cam.position = cam.target + offset;
    if (in.panDrag != vec2(0.0)) {
        // One pixel moves the target plane by one pixel's footprint at the target distance.
        const double worldPerPixel = length(offset) * cam.pixelAngle(std::max(in.viewportHeight, 1.0));
        const CameraBasis b = cam.basis();
        const vec3 shift = (-b.right * in.panDrag.x + b.up * in.panDrag.y) * worldPerPixel;
        cam.position += shift;
        cam.target += shift;
        changed = true;
    }
    return changed;
}

bool flyCamera(Camera& cam, const Formula& f, const CameraInput& in, const CameraControls& c, const DistanceAt& de) {
    bool changed = false;
    vec3 look = cam.target - cam.position;
    const double lookDistance = length(look);
    if (in.rotateDrag != vec2(0.0)) {
        look = turn(look, cam.up, -in.rotateDrag.x * c.degreesPerPixel, -in.rotateDrag.y * c.degreesPerPixel);
        changed = true;
    }
    const CameraBasis b = basisLookingAlong(look, cam.up);
    const vec3 dir = b.right * in.move.x + b.up * in.move.y + b.forward * in.move.z;
    const double boost = in.boost ? 4.0 : 1.0;
    const vec3 step = de ? flyStep(f, de, cam.position, dir, in.dt, boost, c.fly)
                         : flyStep(f, cam.position, dir, in.dt, boost, c.fly);
    if (step != vec3(0.0)) changed = true;
    if (!changed) return false;  // the target rebuilt from the view direction is not bit for bit the same
    cam.position += step;
    cam.target = cam.position + b.forward * lookDistance;
    return true;
}

}  // namespace fraktal::editor
