#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's mandelbulb_eye (fractal_formulas.cpp MandelbulbEyeIteration): a power 2 whose
// latitude is the sum of the angles from both poles, atan2(rho, z) theta_scale +
// atan2(rho, -z) theta2_scale, and whose azimuth is phi phi_scale plus the mirrored azimuth
// (atan2(-y, x), or pi - phi with `phi_mirror`), at radius r^2; axes may be folded to their
// absolute values before and after, then `offset` is added. At the default scales the two
// latitudes sum to pi and the azimuths cancel: the point goes to (0, 0, -r^2). The running
// derivative is Mandelbulber2's 2 r; the angle sums jump across atan2's cut unless the scales
// are whole numbers.
struct MandelbulbEye {
    static constexpr std::string_view id = "mandelbulb_eye";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Mandelbulb eye";
    static constexpr std::string_view help =
        "Power 2 whose angles sum those from both poles (scaled), with |axis| folds before and after, plus offset.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps across atan2's cut unless the angle scales are whole numbers";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"abs_before",
                  ParamType::Vec3,
                  {0.0, 0.0, 0.0},
                  0.0,
                  1.0,
                  "Per axis, 1 folds the axis to its absolute value before the power (0 leaves it)."},
        ParamDecl{"theta_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the angle from +z."},
        ParamDecl{"theta2_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the angle from -z."}
            .labelled("Second theta scale"),
        ParamDecl{"phi_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the azimuth."},
        toggleParam("phi_mirror", false, "The mirrored azimuth is pi - phi rather than atan2(-y, x)."),
        ParamDecl{"abs_after",
                  ParamType::Vec3,
                  {0.0, 0.0, 0.0},
                  0.0,
                  1.0,
                  "Per axis, 1 folds the axis to its absolute value after the power (0 leaves it)."},
        ParamDecl{"offset", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Added after the step."},
    };

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz);
    vec3 v = mix(p.xyz, abs(p.xyz), step(0.5, abs_before));
    float rr = dot(v, v), rho = length(v.xy);
    float theta = atan(rho, v.z) * theta_scale + atan(rho, -v.z) * theta2_scale;
    float phi = rho > 0.0 ? atan(v.y, v.x) : 0.0;
    phi = phi * phi_scale + (phi_mirror > 0.5 ? 3.14159265358979 - phi : (rho > 0.0 ? atan(-v.y, v.x) : 0.0));
    v = rr * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
    p.xyz = mix(v, abs(v), step(0.5, abs_after)) + offset;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 abs_before = a.v3(0), abs_after = a.v3(5), offset = a.v3(6);
        const double theta_scale = a.f(1), theta2_scale = a.f(2), phi_scale = a.f(3), phi_mirror = a.f(4);
        p.w *= 2.0 * length(p.xyz);
        vec3 v = glm::mix(p.xyz, glm::abs(p.xyz), glm::step(vec3(0.5), abs_before));
        double rr = dot(v, v), rho = std::hypot(v.x, v.y);
        double theta = std::atan2(rho, v.z) * theta_scale + std::atan2(rho, -v.z) * theta2_scale;
        double phi = rho > 0.0 ? std::atan2(v.y, v.x) : 0.0;
        phi = phi * phi_scale + (phi_mirror > 0.5 ? 3.14159265358979 - phi : (rho > 0.0 ? std::atan2(-v.y, v.x) : 0.0));
        v = rr * vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
        p.xyz = glm::mix(v, glm::abs(v), glm::step(vec3(0.5), abs_after)) + offset;
    }
};

}  // namespace fraktal::blocks
