#include "core/gl/camera_uniforms.hpp"

namespace fraktal::gl {

CameraLocations::CameraLocations(GLuint program, const CameraUniformNames& names)
    : position(glGetUniformLocation(program, names.position)),
      right(glGetUniformLocation(program, names.right)),
      up(glGetUniformLocation(program, names.up)),
      forward(glGetUniformLocation(program, names.forward)),
      tanHalfFovY(glGetUniformLocation(program, names.tanHalfFovY)),
      halfFovY(glGetUniformLocation(program, names.halfFovY)),
      projection(glGetUniformLocation(program, names.projection)) {}

void setCameraUniforms(const CameraLocations& at, const Camera& camera) {
    const CameraBasis basis = camera.basis();
    auto set3 = [](GLint location, const vec3& v) { glUniform3f(location, float(v.x), float(v.y), float(v.z)); };
    set3(at.position, camera.position);
    set3(at.right, basis.right);
    set3(at.up, basis.up);
    set3(at.forward, basis.forward);
    glUniform1f(at.tanHalfFovY, float(camera.tanHalfFovY()));
    glUniform1f(at.halfFovY, float(glm::radians(camera.fovY) * 0.5));
    glUniform1i(at.projection, int(camera.projection));
}

LensLocations::LensLocations(GLuint program)
    : apertureRadius(glGetUniformLocation(program, "u_apertureRadius")),
      focusDistance(glGetUniformLocation(program, "u_focusDistance")),
      blades(glGetUniformLocation(program, "u_blades")) {}

void setLensUniforms(const LensLocations& at, const ThinLens& lens, const Camera& camera) {
    // The thin lens focuses on a plane across the view axis: a pinhole for the wide projections.
    const bool pinhole = !lens.enabled() || camera.projection != Projection::Perspective;
    glUniform1f(at.apertureRadius, pinhole ? 0.0f : float(lens.apertureRadius));
    glUniform1f(at.focusDistance, float(focusDistanceOf(lens, camera)));
    glUniform1i(at.blades, lens.blades);
}

}  // namespace fraktal::gl
