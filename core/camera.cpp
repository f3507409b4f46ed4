#include "core/camera.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace fraktal {

glm::dmat4 Camera::worldFromCamera() const { return glm::inverse(glm::lookAt(position, target, up)); }

vec3 Camera::rayDirection(double ndcX, double ndcY, double aspect) const {
    const double t = std::tan(glm::radians(fovY) * 0.5);
    const vec3 forward = normalize(target - position);
    const vec3 right = normalize(glm::cross(forward, up));
    const vec3 trueUp = glm::cross(right, forward);
    return normalize(forward + right * (ndcX * t * aspect) + trueUp * (ndcY * t));
}

}  // namespace fraktal
