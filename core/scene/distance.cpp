#include "core/scene/distance.hpp"

namespace fraktal {

DistanceAt cpuDistance(const Formula& f) {
    return [&f](const vec3& p) { return distanceEstimate(f, p); };
}

}  // namespace fraktal
