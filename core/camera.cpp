#include "core/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace fraktal {

glm::dmat4 Camera::worldFromCamera() const {
    glm::dmat4 m = glm::inverse(glm::lookAt(position, target, up));
    if (flipVertical) m[1] = -m[1];  // camera-space y is the image's up
    return m;
}

CameraBasis basisLookingAlong(const vec3& look, const vec3& upHint) {
    const vec3 forward = normalize(look);
    const vec3 right = normalize(glm::cross(forward, upHint));
    return {right, glm::cross(right, forward), forward};
}

CameraBasis Camera::basis() const {
    CameraBasis b = basisLookingAlong(target - position, up);
    if (flipVertical) b.up = -b.up;
    return b;
}

double Camera::tanHalfFovY() const { return std::tan(glm::radians(fovY) * 0.5); }

vec3 Camera::rayDirection(double ndcX, double ndcY, double aspect) const {
    const double t = tanHalfFovY();
    const CameraBasis b = basis();
    return normalize(b.forward + b.right * (ndcX * t * aspect) + b.up * (ndcY * t));
}

}  // namespace fraktal
