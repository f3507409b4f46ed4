#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Benesi's folds in the frame turned so that its z axis is the space diagonal (Mandelbulber2's
// transf_benesi_t1 and the "TM" fold of the pseudo-Kleinian mods, fractal_formulas.cpp): into the
// frame, each axis folded to its absolute value and scaled, and back. The frame change is an
// isometry and |x| keeps distances, so the running derivative grows by the largest |scale|, a
// bound everywhere (Mandelbulber2 takes |scaled| / |v|, plus 1).

// transf_benesi_t1: |v| scaled per axis in Benesi's frame, then `offset` subtracted.
struct BenesiT1 {
    static constexpr std::string_view id = "benesi_t1";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Benesi T1";
    static constexpr std::string_view help =
        "Benesi's fold: |v| scaled per axis in the frame whose z is the space diagonal, less offset.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Vec3, {2.0, 2.0, 2.0}, -8.0, 8.0, "Factor per axis of the turned frame."},
        ParamDecl{"offset", ParamType::Vec3, {2.0, 0.0, 0.0}, -8.0, 8.0, "Subtracted after the fold."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float xz = v.x * 0.816496580927726 - v.z * 0.577350269189626;
    v = vec3((xz - v.y) * 0.707106781186548, (xz + v.y) * 0.707106781186548, v.x * 0.577350269189626 + v.z * 0.816496580927726);
    v = abs(v) * scale;
    xz = (v.y + v.x) * 0.707106781186548;
    v = vec3(v.z * 0.577350269189626 + xz * 0.816496580927726, (v.y - v.x) * 0.707106781186548, v.z * 0.816496580927726 - xz * 0.577350269189626);
    p.xyz = v - offset;
    p.w *= max(abs(scale.x), max(abs(scale.y), abs(scale.z)));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 scale = a.v3(0), offset = a.v3(1);
        vec3 v = p.xyz;
        double xz = v.x * 0.816496580927726 - v.z * 0.577350269189626;
        v = vec3((xz - v.y) * 0.707106781186548, (xz + v.y) * 0.707106781186548,
                 v.x * 0.577350269189626 + v.z * 0.816496580927726);
        v = abs(v) * scale;
        xz = (v.y + v.x) * 0.707106781186548;
        v = vec3(v.z * 0.577350269189626 + xz * 0.816496580927726, (v.y - v.x) * 0.707106781186548,
                 v.z * 0.816496580927726 - xz * 0.577350269189626);
        p.xyz = v - offset;
        p.w *= max(abs(scale.x), max(abs(scale.y), abs(scale.z)));
    }
};

// The pseudo-Kleinian mods' "TM" fold: |v| scaled per axis in Benesi's frame, then Tglad's box fold
// there (|v + L| - |v - L| - v), and back.
struct BenesiBoxFold {
    static constexpr std::string_view id = "benesi_box_fold";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Benesi box fold";
    static constexpr std::string_view help =
        "In the frame whose z is the space diagonal: |v| scaled per axis, then the box fold at limit L.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Vec3, {3.0, 3.0, 3.0}, -8.0, 8.0, "Factor per axis of the turned frame."},
        ParamDecl{"limit", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 8.0, "Box folding limits L in the turned frame."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 v = p.xyz;
    float xz = v.x * 0.816496580927726 - v.z * 0.577350269189626;
    v = vec3((xz - v.y) * 0.707106781186548, (xz + v.y) * 0.707106781186548, v.x * 0.577350269189626 + v.z * 0.816496580927726);
    v = abs(v) * scale;
    v = abs(v + limit) - abs(v - limit) - v;
    xz = (v.y + v.x) * 0.707106781186548;
    p.xyz = vec3(v.z * 0.577350269189626 + xz * 0.816496580927726, (v.y - v.x) * 0.707106781186548, v.z * 0.816496580927726 - xz * 0.577350269189626);
    p.w *= max(abs(scale.x), max(abs(scale.y), abs(scale.z)));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 scale = a.v3(0), limit = a.v3(1);
        vec3 v = p.xyz;
        double xz = v.x * 0.816496580927726 - v.z * 0.577350269189626;
        v = vec3((xz - v.y) * 0.707106781186548, (xz + v.y) * 0.707106781186548,
                 v.x * 0.577350269189626 + v.z * 0.816496580927726);
        v = abs(v) * scale;
        v = abs(v + limit) - abs(v - limit) - v;
        xz = (v.y + v.x) * 0.707106781186548;
        p.xyz = vec3(v.z * 0.577350269189626 + xz * 0.816496580927726, (v.y - v.x) * 0.707106781186548,
                     v.z * 0.816496580927726 - xz * 0.577350269189626);
        p.w *= max(abs(scale.x), max(abs(scale.y), abs(scale.z)));
    }
};

}  // namespace fraktal::blocks
