#include "core/viewport/camera_path.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace fraktal::viewport {

std::optional<CameraPath> parseCameraPath(const std::string& name) {
    if (name == "orbit") return CameraPath::Orbit;
    if (name == "dolly") return CameraPath::Dolly;
    if (name == "pan") return CameraPath::Pan;
    return std::nullopt;
}

const char* toString(CameraPath p) {
    switch (p) {
        case CameraPath::Orbit: return "orbit";
        case CameraPath::Dolly: return "dolly";
        case CameraPath::Pan: return "pan";
    }
    return "?";
}

Camera cameraOnPath(const Camera& start, CameraPath path, int frame, double degreesPerFrame) {
    Camera c = start;
    const double angle = glm::radians(degreesPerFrame * frame);
    switch (path) {
        case CameraPath::Orbit: {
            const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), angle, start.up);
            c.position = start.target + vec3(r * glm::dvec4(start.position - start.target, 0.0));
            break;
        }
        case CameraPath::Dolly:
            c.position = start.target + (start.position - start.target) * std::pow(0.996, frame);
            break;
        case CameraPath::Pan: {
            const glm::dmat4 r = glm::rotate(glm::dmat4(1.0), angle, start.up);
            c.target = start.position + vec3(r * glm::dvec4(start.target - start.position, 0.0));
            break;
        }
    }
    return c;
}

}  // namespace fraktal::viewport
