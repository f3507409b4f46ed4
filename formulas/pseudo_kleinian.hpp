#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Knighty's pseudo-Kleinian (Fragmentarium "PseudoKleinian"): a box fold into [-C, C], then an
// inversion in the sphere of radius sqrt(size) applied only inside it,
// k = max(size / |v|^2, 1). Both keep or scale distances conformally: the running derivative is
// multiplied by k. Close with the pseudo_kleinian estimator.
struct PseudoKleinian {
    static constexpr std::string_view id = "pseudo_kleinian";
    static constexpr std::string_view label = "Pseudo-Kleinian";
    static constexpr std::string_view help =
        "Knighty's pseudo-Kleinian step: box fold into [-C, C], then invert where |v|^2 < size.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr std::array params{
        ParamDecl{"box_size", ParamType::Vec3, {0.92436, 0.90756, 0.92436}, 0.1, 4.0, "Half-size C of the fold box."},
        ParamDecl{"size", ParamType::Float, {1.0, 0.0, 0.0}, 0.1, 4.0, "Squared radius of the inversion sphere."},
    };

    static constexpr std::string_view glsl = R"(
    p.xyz = 2.0 * clamp(p.xyz, -box_size, box_size) - p.xyz;
    float k = max(size / max(dot(p.xyz, p.xyz), 1e-12), 1.0);
    p *= k;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 box_size = a.v3(0);
        const double size = a.f(1);
        p.xyz = 2.0 * clamp(p.xyz, -box_size, box_size) - p.xyz;
        double k = max(size / std::max(dot(p.xyz, p.xyz), 1e-12), 1.0);
        p.xyz *= k, p.w *= k;
    }
};

// The pseudo-Kleinian formulas' prism fold (Mandelbulber2's "prism shape", fractal_formulas.cpp
// PseudoKleinianIteration and its mods): |y| and |z|; x and y moved along (sqrt 3, -1) by
// t = max(0, scale (y / 2 - x sqrt(3) / 2)) (at scale 1 the reflection in the plane at 60 degrees),
// y folded to |y - t|; y and z sorted; shifted by gap (sqrt(3)/2, 3/2, 3/2); z and x sorted;
// where x > 0, y and z clamped at 0. The moving part is I - 2 scale n n^T (n the plane's unit
// normal), which stretches by max(1, |1 - 2 scale|); the clamp where x > 0 makes the map jump
// across x = 0.
struct PrismFold {
    static constexpr std::string_view id = "prism_fold";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Prism fold";
    static constexpr std::string_view help =
        "The pseudo-Kleinian prism shape: folds onto a 60-degree wedge, sorts, shifts by gap, clamps.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps across x = 0, where it clamps y and z at 0 on one side";
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 4.0, "Strength of the 60-degree fold (1 reflects)."},
        ParamDecl{"gap", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Shift, times (sqrt(3)/2, 3/2, 3/2)."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = vec3(p.x, abs(p.y), abs(p.z));
    float t = max(0.0, (v.x * -0.866025403784439 + v.y * 0.5) * scale);
    v.x += t * 1.73205080756888;
    v.y = abs(v.y - t);
    if (v.y > v.z) v.yz = v.zy;
    v -= gap * vec3(0.866025403784439, 1.5, 1.5);
    if (v.z > v.x) v.xz = v.zx;
    if (v.x > 0.0) v.yz = max(v.yz, 0.0);
    p.xyz = v;
    p.w *= max(1.0, abs(1.0 - 2.0 * scale));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0);
        const vec3 gap = a.v3(1);
        vec3 v = vec3(p.xyz.x, abs(p.xyz.y), abs(p.xyz.z));
        double t = std::max(0.0, (v.x * -0.866025403784439 + v.y * 0.5) * scale);
        v.x += t * 1.73205080756888;
        v.y = abs(v.y - t);
        if (v.y > v.z) std::swap(v.y, v.z);
        v -= gap * vec3(0.866025403784439, 1.5, 1.5);
        if (v.z > v.x) std::swap(v.x, v.z);
        if (v.x > 0.0) v.y = std::max(v.y, 0.0), v.z = std::max(v.z, 0.0);
        p.xyz = v;
        p.w *= max(1.0, abs(1.0 - 2.0 * scale));
    }
};

// Knighty's pseudo-Kleinian distance: the orbit's end point against a thin cylinder about the
// z axis, max(rxy - thickness, |rxy z| / r), over the running derivative, less offset
// (Knighty's DEoffset, Fragmentarium "PseudoKleinian.frag", subtracted after the division as
// there). The limit set's sheets have no inside of their own (the estimate stays above 0); the
// offset thickens them by that much in world units, so a marcher's hit threshold and the
// baseline marcher's fixed step both meet a solid of known thickness.
struct PseudoKleinianEstimator {
    static constexpr std::string_view id = "pseudo_kleinian_de";
    static constexpr std::string_view label = "Pseudo-Kleinian distance";
    static constexpr std::string_view help = "Knighty's pseudo-Kleinian estimate, over the running derivative.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"thickness", ParamType::Float, {0.01, 0.0, 0.0}, 0.0, 1.0, "Thickness of the limit set's sheets."},
        ParamDecl{"offset",
                  ParamType::Float,
                  {0.004, 0.0, 0.0},
                  0.0,
                  0.1,
                  "Subtracted after the division (Knighty's DEoffset): thickens the sheets by this much."},
    };

    static constexpr std::string_view glsl = R"(
    float rxy = length(p.xy);
    return max(rxy - thickness, abs(rxy * p.z) / max(length(p.xyz), 1e-12)) / abs(p.w) - offset;
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double thickness = a.f(0), offset = a.f(1);
        double rxy = std::hypot(p.xyz.x, p.xyz.y);
        return max(rxy - thickness, abs(rxy * p.xyz.z) / std::max(length(p.xyz), 1e-12)) / abs(p.w) - offset;
    }
};

}  // namespace fraktal::blocks
