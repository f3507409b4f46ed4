#pragma once
#include <algorithm>

#include "core/scene_object.hpp"

// The kinds of object beside the fractal (core/scene_object.hpp): each a signed distance in its
// own frame (Inigo Quilez, "distance functions", iquilezles.org; Mandelbulber2's primitives.cpp
// for the plane, cylinder and torus conventions).
namespace fraktal::objects {

// Solid below the plane z = 0 of its frame (the normal is the frame's z).
struct Plane {
    static constexpr std::string_view id = "plane";
    static constexpr std::string_view label = "Plane";
    static constexpr std::string_view help = "The half-space below z = 0 of the object's frame (turn it to tilt it).";
    static constexpr std::array<ParamDecl, 0> params{};
    static constexpr std::string_view glsl = R"(
    return pos.z;
)";
    static double distance(const vec3& pos, Args) { return pos.z; }
};

// A box of half-sizes `size`, its edges rounded by `rounding` (which grows it by that much).
struct Box {
    static constexpr std::string_view id = "box";
    static constexpr std::string_view label = "Box";
    static constexpr std::string_view help = "A box of half-sizes along x, y and z, its edges rounded.";
    static constexpr std::array params{
        ParamDecl{"size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 1000.0, "Half-sizes along x, y and z."},
        ParamDecl{"rounding", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 100.0, "Radius of the rounded edges."},
    };
    static constexpr std::string_view glsl = R"(
    vec3 q = abs(pos) - size;
    return length(max(q, vec3(0.0))) + min(max(q.x, max(q.y, q.z)), 0.0) - rounding;
)";
    static double distance(const vec3& pos, Args a) {
        const vec3 size = a.v3(0);
        const double rounding = a.f(1);
        const vec3 q = abs(pos) - size;
        return length(max(q, vec3(0.0))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0) - rounding;
    }
};

struct Sphere {
    static constexpr std::string_view id = "sphere";
    static constexpr std::string_view label = "Sphere";
    static constexpr std::string_view help = "A ball about the object's centre.";
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 1000.0, "Radius."},
    };
    static constexpr std::string_view glsl = R"(
    return length(pos) - radius;
)";
    static double distance(const vec3& pos, Args a) { return length(pos) - a.f(0); }
};

// A cylinder about the frame's z axis, `height` long (centred); without caps, a tube: the wall
// alone, open at the ends.
struct Cylinder {
    static constexpr std::string_view id = "cylinder";
    static constexpr std::string_view label = "Cylinder";
    static constexpr std::string_view help = "A cylinder about z, its length centred; without caps an open tube.";
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 1000.0, "Radius."},
        ParamDecl{"height", ParamType::Float, {2.0, 0.0, 0.0}, 0.0, 1000.0, "Length along z."},
        toggleParam("caps", true, "On: closed at the ends; off: the wall alone."),
    };
    static constexpr std::string_view glsl = R"(
    float wall = length(pos.xy) - radius;
    if (caps < 0.5) wall = abs(wall);
    return max(abs(pos.z) - height * 0.5, wall);
)";
    static double distance(const vec3& pos, Args a) {
        const double radius = a.f(0), height = a.f(1), caps = a.f(2);
        double wall = std::hypot(pos.x, pos.y) - radius;
        if (caps < 0.5) wall = std::abs(wall);
        return std::max(std::abs(pos.z) - height * 0.5, wall);
    }
};

// A torus about the frame's z axis: the ring of radius `radius`, the tube of radius `tube`.
struct Torus {
    static constexpr std::string_view id = "torus";
    static constexpr std::string_view label = "Torus";
    static constexpr std::string_view help = "A torus about z: a ring and the tube around it.";
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 1000.0, "Radius of the ring."},
        ParamDecl{"tube", ParamType::Float, {0.25, 0.0, 0.0}, 0.0, 1000.0, "Radius of the tube."},
    };
    static constexpr std::string_view glsl = R"(
    return length(vec2(length(pos.xy) - radius, pos.z)) - tube;
)";
    static double distance(const vec3& pos, Args a) {
        return std::hypot(std::hypot(pos.x, pos.y) - a.f(0), pos.z) - a.f(1);
    }
};

}  // namespace fraktal::objects
