// Random vectors whose components are drawn in one fixed order.
//
// C++ leaves the order in which a call's arguments are evaluated unspecified: GCC evaluates
// vec3(u(rng), u(rng), u(rng)) last argument first and clang first argument first, so one seed
// gave the two compilers different points and rays, and with them different measured step
// factors, fitted estimators and test outcomes. These draw the last component first, GCC's order,
// in which the shipped factors and the figures in the bench tables were measured.
#pragma once

#include "core/vec.hpp"

namespace fraktal {

template <class Distribution, class Engine>
vec2 randomVec2(Distribution& distribution, Engine& engine) {
    const double y = distribution(engine);
    const double x = distribution(engine);
    return {x, y};
}

template <class Distribution, class Engine>
vec3 randomVec3(Distribution& distribution, Engine& engine) {
    const double z = distribution(engine);
    const double y = distribution(engine);
    const double x = distribution(engine);
    return {x, y, z};
}

}  // namespace fraktal
