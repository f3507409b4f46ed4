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

double Camera::pixelAngle(double imageHeight, double imageWidth) const {
    if (projection == Projection::Perspective) return 2.0 * tanHalfFovY() / imageHeight;
    const double angle = glm::radians(fovY) / imageHeight;
    if (projection == Projection::FishEye || imageWidth <= 0.0) return angle;
    return std::max(angle, 2.0 * glm::radians(fovY) / imageWidth);
}

double Camera::tanHalfFovY() const { return std::tan(glm::radians(fovY) * 0.5); }

// Mirror of projectionRay in shaders/camera.glsl.
vec3 Camera::rayDirection(double ndcX, double ndcY, double aspect) const {
    const CameraBasis b = basis();
    const double halfFovY = glm::radians(fovY) * 0.5;
    if (projection == Projection::FishEye) {
        const glm::dvec2 v(ndcX * aspect, ndcY);
        const double r = glm::length(v), theta = r * halfFovY;
        const glm::dvec2 across = r > 0.0 ? v / r * std::sin(theta) : glm::dvec2(0.0);
        return normalize(b.forward * std::cos(theta) + b.right * across.x + b.up * across.y);
    }
    if (projection == Projection::Equirectangular) {
        const double longitude = ndcX * 2.0 * halfFovY, latitude = ndcY * halfFovY;
        return normalize((b.forward * std::cos(longitude) + b.right * std::sin(longitude)) * std::cos(latitude) +
                         b.up * std::sin(latitude));
    }
    const double t = tanHalfFovY();
    return normalize(b.forward + b.right * (ndcX * t * aspect) + b.up * (ndcY * t));
}

}  // namespace fraktal
