#include "core/gl/camera_uniforms.hpp"

namespace fraktal::gl {

void setCameraUniforms(GLuint program, const Camera& camera, const CameraUniformNames& names) {
    const CameraBasis basis = camera.basis();
    auto set3 = [&](const char* name, const vec3& v) {
        glUniform3f(glGetUniformLocation(program, name), float(v.x), float(v.y), float(v.z));
    };
    set3(names.position, camera.position);
    set3(names.right, basis.right);
    set3(names.up, basis.up);
    set3(names.forward, basis.forward);
    glUniform1f(glGetUniformLocation(program, names.tanHalfFovY), float(camera.tanHalfFovY()));
}

}  // namespace fraktal::gl
