// The camera uniforms of the ray-marching shaders (shaders/still.frag, shaders/viewport_common.glsl):
// the position, the frame of Camera::basis and tan(fovY / 2), from which each shader builds its
// rays exactly as Camera::rayDirection does.
#pragma once

#include <epoxy/gl.h>

#include "core/camera.hpp"

namespace fraktal::gl {

struct CameraUniformNames {
    const char *position, *right, *up, *forward, *tanHalfFovY;
};
inline constexpr CameraUniformNames kCameraUniforms{"u_cameraPosition", "u_cameraRight", "u_cameraUp",
                                                    "u_cameraForward", "u_tanHalfFovY"};

// Sets them on `program`, which must be in use.
void setCameraUniforms(GLuint program, const Camera& camera, const CameraUniformNames& names = kCameraUniforms);

}  // namespace fraktal::gl
