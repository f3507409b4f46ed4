#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Steps in four dimensions. The orbit carries the point's fourth coordinate w beside xyz
// (P4::pointW; GLSL: the global pointW), 0 when each orbit starts, as Mandelbulber2's CVector4 z
// carries z.w (compute_fractal.cpp). The 3D scene is then the slice of a 4D fractal at the w the
// orbit starts from. The bailout and the linear estimate measure r in 4D (Mandelbulber2's
// z.Length()); steps that do not read w leave it as it is. A 4D step that folds by mirrors and
// scales by s stretches the 4D point by |s|, which bounds the stretch of its xyz part too.

// The fourth coordinate the orbit starts from (Mandelbulber2's initial_waxis): the slice's w.
struct StartW {
    static constexpr std::string_view id = "start_w";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Fourth coordinate";
    static constexpr std::string_view help =
        "On the first iteration, set the point's fourth coordinate w (else 0) for the 4D steps after it: the scene "
        "is the slice of their 4D fractal at that w (Mandelbulber2's initial w axis).";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"w", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "The fourth coordinate on iteration 0."},
    };

    static constexpr std::string_view glsl = R"(
    if (iteration == 0) pointW = w;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double w = a.f(0);
        if (p.iteration == 0) p.pointW = w;
    }
};

// Mandelbulber2's menger4d (fractal_formulas.cpp Menger4dIteration; Syntopia's and DarkBeam's
// Menger4 from Mandelbulb 3D): the absolute value of the 4D point, its coordinates sorted largest
// first (the six swaps: mirrors across the planes x = y ...), then x, y and w scaled about the
// offset's corner, z folded about the middle layer as the 3D sponge's. Mirrors and a scale: the
// running derivative grows by |s|.
struct Menger4d {
    static constexpr std::string_view id = "menger4d";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Menger sponge 4D";
    static constexpr std::string_view help =
        "The Menger sponge in 4D: |x|, |y|, |z|, |w| sorted largest first, then scaled by s about the offset corner, "
        "z folded about the middle layer.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {3.0, 0.0, 0.0}, 0.1, 4.0, "Scale s per iteration."},
        ParamDecl{"offset", ParamType::Vec3, {1.0, 1.0, 1.0}, -20.0, 20.0, "Corner the scaling keeps fixed (x, y, z)."},
        ParamDecl{"offset_w", ParamType::Float, {1.0, 0.0, 0.0}, -20.0, 20.0, "The corner's fourth coordinate."},
    };

    static constexpr std::string_view glsl = R"(
    vec4 z = abs(vec4(p.xyz, pointW));
    if (z.x < z.y) z.xy = z.yx;
    if (z.x < z.z) z.xz = z.zx;
    if (z.y < z.z) z.yz = z.zy;
    if (z.x < z.w) z.xw = z.wx;
    if (z.y < z.w) z.yw = z.wy;
    if (z.z < z.w) z.zw = z.wz;
    z.xyw = scale * z.xyw - vec3(offset.xy, offset_w);
    float middle = 0.5 * offset.z / scale;
    z.z = scale * (middle - abs(z.z - middle));
    p.xyz = z.xyz;
    pointW = z.w;
    p.w *= abs(scale);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), offset_w = a.f(2);
        const vec3 offset = a.v3(1);
        vec4 z = abs(vec4(p.xyz, p.pointW));
        if (z.x < z.y) std::swap(z.x, z.y);
        if (z.x < z.z) std::swap(z.x, z.z);
        if (z.y < z.z) std::swap(z.y, z.z);
        if (z.x < z.w) std::swap(z.x, z.w);
        if (z.y < z.w) std::swap(z.y, z.w);
        if (z.z < z.w) std::swap(z.z, z.w);
        z.x = scale * z.x - offset.x;
        z.y = scale * z.y - offset.y;
        z.w = scale * z.w - offset_w;
        double middle = 0.5 * offset.z / scale;
        z.z = scale * (middle - abs(z.z - middle));
        p.xyz = vec3(z);
        p.pointW = z.w;
        p.w *= abs(scale);
    }
};

// Mandelbulber2's sierpinski4d (fractal_formulas.cpp Sierpinski4dIteration): the 4D point mirrored
// across the six planes x + y = 0 ... z + w = 0 where it lies on their negative side, then scaled
// by s and moved back by the offset (the 4D simplex's vertex). Mirrors and a scale: the running
// derivative grows by |s|.
struct Sierpinski4d {
    static constexpr std::string_view id = "sierpinski4d";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Sierpinski 4D";
    static constexpr std::string_view help =
        "The Sierpinski simplex in 4D: mirror across x + y = 0 ... z + w = 0, then scale by s and subtract the offset.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {2.0, 0.0, 0.0}, -4.0, 4.0, "Scale s per iteration."},
        ParamDecl{"offset", ParamType::Vec3, {1.0, 1.0, 1.0}, -20.0, 20.0, "Subtracted after the scale (x, y, z)."},
        ParamDecl{"offset_w", ParamType::Float, {1.0, 0.0, 0.0}, -20.0, 20.0, "The offset's fourth coordinate."},
    };

    static constexpr std::string_view glsl = R"(
    vec4 z = vec4(p.xyz, pointW);
    if (z.x + z.y < 0.0) z.xy = -z.yx;
    if (z.x + z.z < 0.0) z.xz = -z.zx;
    if (z.y + z.z < 0.0) z.yz = -z.zy;
    if (z.x + z.w < 0.0) z.xw = -z.wx;
    if (z.y + z.w < 0.0) z.yw = -z.wy;
    if (z.z + z.w < 0.0) z.zw = -z.wz;
    z = z * scale - vec4(offset, offset_w);
    p.xyz = z.xyz;
    pointW = z.w;
    p.w *= abs(scale);
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), offset_w = a.f(2);
        const vec3 offset = a.v3(1);
        vec4 z = vec4(p.xyz, p.pointW);
        auto mirror = [](double& u, double& v) {
            if (u + v < 0.0) {
                const double t = u;
                u = -v;
                v = -t;
            }
        };
        mirror(z.x, z.y);
        mirror(z.x, z.z);
        mirror(z.y, z.z);
        mirror(z.x, z.w);
        mirror(z.y, z.w);
        mirror(z.z, z.w);
        z = z * scale - vec4(offset, offset_w);
        p.xyz = vec3(z);
        p.pointW = z.w;
        p.w *= abs(scale);
    }
};

}  // namespace fraktal::blocks
