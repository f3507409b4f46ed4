// A pinhole camera looking from `position` at `target`.
#pragma once

#include <string_view>

#include "core/vec.hpp"

namespace fraktal {

// A right-handed orthonormal frame: the viewer looks along `forward`, with `up` toward the top of
// the image and `right` toward its right edge.
struct CameraBasis {
    vec3 right, up, forward;
};

// The frame looking along `look` (any length) whose up is as close to `upHint` as the look allows.
CameraBasis basisLookingAlong(const vec3& look, const vec3& upHint);

// How directions map onto the image (shaders/camera.glsl, which says how each maps).
enum class Projection {
    Perspective,      // the pinhole: straight lines stay straight; fovY below 180 degrees
    FishEye,          // equidistant: the angle from the view axis grows with the distance from the centre
    Equirectangular,  // longitude across (2 fovY), latitude up (fovY): at fovY 180 the whole sphere
};
// The preset's names ("perspective", "fisheye", "equirectangular"), in enum order.
inline constexpr std::string_view kProjectionNames[] = {"perspective", "fisheye", "equirectangular"};

struct Camera {
    vec3 position{0.0, 0.0, 4.0};
    vec3 target{0.0};
    vec3 up{0.0, 1.0, 0.0};
    double fovY = 40.0;  // vertical field of view, degrees
    // The image mirrored top to bottom: the frame's up is reversed (a left-handed frame). Only
    // pictures from another program need it: Mandelbulber2's legacy_coordinate_system (the v1.x
    // picture) is the standard one mirrored, which no camera pose reproduces.
    bool flipVertical = false;
    Projection projection = Projection::Perspective;

    bool operator==(const Camera&) const = default;

    // Camera space: x right, y up, looking down -z (OpenGL convention).
    glm::dmat4 worldFromCamera() const;
    // Direction in world space of the ray through normalised device coordinates (-1..1).
    vec3 rayDirection(double ndcX, double ndcY, double aspect) const;
    // The frame of every ray: rayDirection, the GLSL cameraRay (shaders) and the editor's controls.
    CameraBasis basis() const;
    double tanHalfFovY() const;
    // A pixel's footprint per unit distance along the ray, in an image `imageHeight` pixels tall
    // and `imageWidth` wide: at the centre of a pinhole's image; everywhere for a fish eye; the
    // larger of the two directions' for an equirectangular image, which spans 2 fovY across
    // whatever its width (a width of 0: taken as 2:1). Mirror of projectionPixelAngle in
    // shaders/camera.glsl.
    double pixelAngle(double imageHeight, double imageWidth = 0.0) const;
};

}  // namespace fraktal
