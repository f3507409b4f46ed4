#pragma once
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// The polygonal fold of the xy plane: x mirrored to x >= 0, then the point's angle folded into a
// wedge of the n-gon's symmetry, keeping its distance from the z axis. Mandelbulber2's dIFS
// formulas write it as psi = |fmod(atan(y / x) + pi / n, 2 pi / n) - pi / n| and (x, y) = |xy|
// (cos psi, sin psi) (DIFSBoxV1Iteration and DIFSCylinderIteration, "polyfold", in
// fractal_formulas.cpp of 2.20). fmod truncates towards zero, so an angle below -pi / n is not
// wrapped into the wedge but mirrored about pi / (2 n): the map is Mandelbulber2's, not a
// kaleidoscope's. Each region is turned or mirrored about the z axis, so the running derivative is
// unchanged, but the truncation jumps where the shifted angle crosses a negative multiple of the
// wedge (psi goes from pi / n to 3 pi / n there): two points on either side of such a ray land
// apart (SafeStep.GlobalBoundsHoldBetweenDistantPoints found them), so no bound holds across it.
struct PolyFold {
    static constexpr std::string_view id = "poly_fold";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Polygonal fold";
    static constexpr std::string_view help =
        "Folds the xy plane into a wedge of an n-gon: x becomes |x|, the angle about z is folded by "
        "|fmod(angle + pi/n, 2 pi/n) - pi/n| and the distance from z kept (Mandelbulber2's dIFS polyfold).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where the angle, shifted by half a wedge, crosses a negative multiple of the wedge "
        "(Mandelbulber2's truncating fmod)";
    static constexpr std::array params{
        ParamDecl{"order", ParamType::Float, {6.0, 0.0, 0.0}, 1.0, 32.0, "n: the polygon's number of sides."},
    };

    // GLSL's mod floors; C's fmod truncates, which the negative angles need (see above).
    static constexpr std::string_view glsl = R"(
    float n = max(floor(order + 0.5), 1.0);
    float x = abs(p.x);
    float half_wedge = radians(180.0) / n;
    float a = atan(p.y, x) + half_wedge;
    float period = 2.0 * half_wedge;
    float psi = abs(a - period * trunc(a / period) - half_wedge);
    float len = length(vec2(x, p.y));
    p.xy = len * vec2(cos(psi), sin(psi));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double n = std::max(std::floor(a.f(0) + 0.5), 1.0);
        const double x = std::abs(p.xyz.x), y = p.xyz.y;
        const double psi = std::abs(std::fmod(std::atan2(y, x) + M_PI / n, 2.0 * M_PI / n) - M_PI / n);
        const double len = std::sqrt(x * x + y * y);
        p.xyz.x = len * std::cos(psi);
        p.xyz.y = len * std::sin(psi);
    }
};

}  // namespace fraktal::blocks
