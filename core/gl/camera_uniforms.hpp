// The camera uniforms of the ray-marching shaders (shaders/still.frag, shaders/viewport_common.glsl,
// shaders/pathtrace.frag, and the lens of shaders/lens.glsl):
// the position, the frame of Camera::basis and tan(fovY / 2), from which each shader builds its
// rays exactly as Camera::rayDirection does.
#pragma once

#include <epoxy/gl.h>

#include "core/camera.hpp"
#include "core/lighting.hpp"

namespace fraktal::gl {

struct CameraUniformNames {
    const char *position, *right, *up, *forward, *tanHalfFovY, *halfFovY, *projection;
};
inline constexpr CameraUniformNames kCameraUniforms{"u_cameraPosition", "u_cameraRight", "u_cameraUp",
                                                    "u_cameraForward",  "u_tanHalfFovY", "u_halfFovY",
                                                    "u_projection"};

// Their locations in one program, looked up once when it is built (-1: not in the program).
struct CameraLocations {
    GLint position = -1, right = -1, up = -1, forward = -1, tanHalfFovY = -1, halfFovY = -1, projection = -1;
    CameraLocations() = default;
    explicit CameraLocations(GLuint program, const CameraUniformNames& names = kCameraUniforms);
};

// Sets them on the program they were found in, which must be in use.
void setCameraUniforms(const CameraLocations& at, const Camera& camera);

// The thin lens's uniforms (shaders/lens.glsl), found the same way; a pinhole sets aperture 0.
struct LensLocations {
    GLint apertureRadius = -1, focusDistance = -1, blades = -1;
    LensLocations() = default;
    explicit LensLocations(GLuint program);
};
void setLensUniforms(const LensLocations& at, const ThinLens& lens, const Camera& camera);

}  // namespace fraktal::gl
