// A pinhole camera looking from `position` at `target`.
#pragma once

#include "core/vec.hpp"

namespace fraktal {

struct Camera {
    vec3 position{0.0, 0.0, 4.0};
    vec3 target{0.0};
    vec3 up{0.0, 1.0, 0.0};
    double fovY = 40.0;  // vertical field of view, degrees

    // Camera space: x right, y up, looking down -z (OpenGL convention).
    glm::dmat4 worldFromCamera() const;
    // Direction in world space of the ray through normalised device coordinates (-1..1).
    vec3 rayDirection(double ndcX, double ndcY, double aspect) const;
};

}  // namespace fraktal
