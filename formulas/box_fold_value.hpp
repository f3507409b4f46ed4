#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's box fold as it writes it, with a folding value V beside the limit L (2.20's
// BoxFolding, the global box fold of its main parameters, and MandelboxIteration's
// mandelbox_folding_value, fractal_formulas.cpp): a coordinate above L becomes V - x, one below -L
// becomes -V - x. At V = 2 L it is the box fold, a reflection at the limit; otherwise the map jumps
// by V - 2 L where a coordinate crosses the limit. Either way it is a reflection and a shift in
// each axis, so the running derivative is unchanged, as Mandelbulber2 leaves it.
struct BoxFoldValue {
    static constexpr std::string_view id = "box_fold_value";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Box fold, own value";
    static constexpr std::string_view help =
        "Box fold with a folding value V of its own: a coordinate x above the limit L becomes V - x, below -L it "
        "becomes -V - x (V = 2 L is the plain box fold; otherwise the map jumps at the limit).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps by V - 2 L where a coordinate crosses the limit, unless the value is twice the limit";
    static DerivativeBound derivativeFor(Args a) {
        return a.f(1) == 2.0 * a.f(0) ? DerivativeBound::Global : DerivativeBound::None;
    }
    static constexpr std::array params{
        ParamDecl{"limit", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 8.0, "Folding limit L."},
        ParamDecl{"value", ParamType::Float, {2.0, 0.0, 0.0}, 0.0, 16.0, "Folding value V: x > L becomes V - x."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 q = p.xyz;
    p.xyz = mix(q, sign(q) * value - q, greaterThan(abs(q), vec3(limit)));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double limit = a.f(0), value = a.f(1);
        for (int k = 0; k < 3; ++k) {
            const double x = p.xyz[k];
            if (x > limit)
                p.xyz[k] = value - x;
            else if (x < -limit)
                p.xyz[k] = -value - x;
        }
    }
};

}  // namespace fraktal::blocks
