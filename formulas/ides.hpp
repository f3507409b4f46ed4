#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Trafassel's Ide's formula (Mandelbulber2's ides and ides2, from Mandelbulb3D; fractalforums.com
// "formula 21 (julia set interpretation)"): (m.x x^2 - s.x (y^2 + z^2), m.y x y z,
// m.z z^2 - s.z (x^2 + y^2)), with `damp` x and z first times 0.9 where under 2.5 in size (ides),
// with `keep` the point added to the result (ides2). The running derivative is the Jacobian's
// Frobenius norm (plus 1 with `keep`), which bounds its largest stretch; the damping jumps.
struct Ides {
    static constexpr std::string_view id = "ides";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Ide's formula";
    static constexpr std::string_view help =
        "Trafassel's (m.x x^2 - s.x (y^2 + z^2), m.y xyz, m.z z^2 - s.z (x^2 + y^2)), x and z damped or the point "
        "kept.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where |x| or |z| crosses 2.5 (the damping)";
    static DerivativeBound derivativeFor(Args a) {
        return a.f(2) > 0.5 ? DerivativeBound::None : DerivativeBound::Local;
    }
    static constexpr Degree degree{{}, 3.0};
    static constexpr std::array params{
        ParamDecl{"multiplier", ParamType::Vec3, {1.0, 2.0, 1.0}, -4.0, 4.0, "m: times x^2, xyz and z^2."},
        ParamDecl{"subtract",
                  ParamType::Vec3,
                  {0.5, 0.5, 0.5},
                  -4.0,
                  4.0,
                  "s: x less s.x (y^2 + z^2), z less s.z "
                  "(x^2 + y^2) (y unused)."},
        toggleParam("damp", true, "On: x and z times 0.9 first where under 2.5 in size (ides)."),
        toggleParam("keep", false, "On: the point added to the result (ides2)."),
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    if (damp > 0.5) {
        if (abs(v.x) < 2.5) v.x *= 0.9;
        if (abs(v.z) < 2.5) v.z *= 0.9;
    }
    vec3 v2 = v * v;
    vec3 m2 = multiplier * multiplier, s2 = subtract * subtract;
    float frobenius2 = 4.0 * m2.x * v2.x + 4.0 * s2.x * (v2.y + v2.z) + m2.y * (v2.y * v2.z + v2.x * v2.z + v2.x * v2.y) +
                       4.0 * s2.z * (v2.x + v2.y) + 4.0 * m2.z * v2.z;
    p.w *= sqrt(frobenius2) + (keep > 0.5 ? 1.0 : 0.0);
    vec3 image = vec3(multiplier.x * v2.x - subtract.x * (v2.y + v2.z), multiplier.y * v.x * v.y * v.z,
                      multiplier.z * v2.z - subtract.z * (v2.x + v2.y));
    p.xyz = keep > 0.5 ? image + v : image;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 multiplier = a.v3(0), subtract = a.v3(1);
        const bool damp = a.f(2) > 0.5, keep = a.f(3) > 0.5;
        vec3 v = p.xyz;
        if (damp) {
            if (abs(v.x) < 2.5) v.x *= 0.9;
            if (abs(v.z) < 2.5) v.z *= 0.9;
        }
        const vec3 v2 = v * v, m2 = multiplier * multiplier, s2 = subtract * subtract;
        const double frobenius2 = 4.0 * m2.x * v2.x + 4.0 * s2.x * (v2.y + v2.z) +
                                  m2.y * (v2.y * v2.z + v2.x * v2.z + v2.x * v2.y) + 4.0 * s2.z * (v2.x + v2.y) +
                                  4.0 * m2.z * v2.z;
        p.w *= std::sqrt(frobenius2) + (keep ? 1.0 : 0.0);
        const vec3 image = vec3(multiplier.x * v2.x - subtract.x * (v2.y + v2.z), multiplier.y * v.x * v.y * v.z,
                                multiplier.z * v2.z - subtract.z * (v2.x + v2.y));
        p.xyz = keep ? image + v : image;
    }
};

// Aexion's octopus (Mandelbulber2's aexion_octopus_mod): (s.x x z, s.y (x^2 - z^2), y), with the
// abs of the chosen axes. Its Jacobian's x-z block has orthogonal rows of lengths |s.x| rho and
// 2 |s.y| rho (rho = (x^2 + z^2)^(1/2)) and y maps to z alone, so its largest stretch is
// max(|s.x| rho, 2 |s.y| rho, 1): the running derivative, a bound (abs keeps lengths).
struct AexionOctopus {
    static constexpr std::string_view id = "aexion_octopus";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Aexion's octopus";
    static constexpr std::string_view help = "Aexion's (s.x xz, s.y (x^2 - z^2), y), the abs of the chosen axes taken.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"x_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "s.x: times x z."},
        ParamDecl{"y_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "s.y: times x^2 - z^2."},
        ParamDecl{"abs_axes", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 1.0, "Per axis, 1 takes the result's abs."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float rho = length(v.xz);
    p.w *= max(max(abs(x_scale) * rho, 2.0 * abs(y_scale) * rho), 1.0);
    vec3 image = vec3(x_scale * v.x * v.z, y_scale * (v.x * v.x - v.z * v.z), v.y);
    p.xyz = mix(image, abs(image), step(0.5, abs_axes));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double x_scale = a.f(0), y_scale = a.f(1);
        const vec3 abs_axes = a.v3(2), v = p.xyz;
        const double rho = std::hypot(v.x, v.z);
        p.w *= max(max(abs(x_scale) * rho, 2.0 * abs(y_scale) * rho), 1.0);
        const vec3 image(x_scale * v.x * v.z, y_scale * (v.x * v.x - v.z * v.z), v.y);
        p.xyz = glm::mix(image, abs(image), glm::step(vec3(0.5), abs_axes));
    }
};

}  // namespace fraktal::blocks
