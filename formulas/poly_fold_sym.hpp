#pragma once
#include <algorithm>
#include <cmath>

#include "core/block.hpp"

namespace fraktal::blocks {

// Mandelbulber2's symmetric polygonal fold of one coordinate plane (transf_poly_fold_sym_multi,
// TransfPolyFoldSymMultiIteration in fractal_formulas.cpp of 2.20). In the plane (a, b) (xy, yz or
// zx), the sector k = trunc(-n atan(a / b) / (2 pi)) turns the point by k 2 pi / n, and an odd
// sector mirrors b after the turn. With `full_turn` the angle is atan2(a, b) over the whole turn;
// without it atan(a / b), which folds the half plane b < 0 onto b > 0's sectors. Each region is
// turned or mirrored, so distances within it are kept, but the truncation gives a sector that
// spans the angle 0 twice the width of the others, and the mirror of the odd sectors does not
// meet the turn of their neighbours: the map jumps at the sector boundaries, and no bound holds
// across them.
struct PolyFoldSym {
    static constexpr std::string_view id = "poly_fold_sym";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Symmetric polygonal fold";
    static constexpr std::string_view help =
        "Turns the point in one coordinate plane by its sector's multiple of 2 pi/n, mirroring odd sectors "
        "(Mandelbulber2's transf_poly_fold_sym_multi, one plane).";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps at the sector boundaries (the truncated sector index and the odd sectors' mirror)";
    static constexpr std::array params{
        ParamDecl{"order", ParamType::Float, {6.0, 0.0, 0.0}, 1.0, 32.0, "n: the number of sectors (rounded)."},
        ParamDecl{
            "plane", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 2.0, "The plane (a, b): 0 xy, 1 yz, 2 zx (rounded)."},
        toggleParam("full_turn", false, "The sector from atan2(a, b) over the whole turn (off: atan(a / b))."),
    };

    // atan(a / b) is written as atan2(a, b) less a half turn where b < 0, so that b = 0 needs no
    // division on either side.
    static constexpr std::string_view glsl = R"(
    float n = max(floor(order + 0.5), 1.0);
    int i = int(clamp(floor(plane + 0.5), 0.0, 2.0));
    int j = i == 2 ? 0 : i + 1;
    float a = p.xyz[i], b = p.xyz[j];
    float t = atan(a, b);
    if (full_turn < 0.5 && b < 0.0) t -= a >= 0.0 ? radians(180.0) : -radians(180.0);
    int sector = int(-n / radians(360.0) * t);
    float angle = float(sector) * radians(360.0) / n;
    float turnedA = a * cos(angle) - b * sin(angle);
    float turnedB = a * sin(angle) + b * cos(angle);
    if ((sector & 1) != 0) turnedB = -turnedB;
    p.xyz[i] = turnedA;
    p.xyz[j] = turnedB;
)";
    static void apply(P4& p, const vec3&, Args args) {
        const double n = std::max(std::floor(args.f(0) + 0.5), 1.0);
        const int i = int(std::clamp(std::floor(args.f(1) + 0.5), 0.0, 2.0));
        const int j = i == 2 ? 0 : i + 1;
        const double a = p.xyz[i], b = p.xyz[j];
        double t = std::atan2(a, b);
        if (args.f(2) < 0.5 && b < 0.0) t -= a >= 0.0 ? M_PI : -M_PI;
        const int sector = int(-n / (2.0 * M_PI) * t);
        const double angle = double(sector) * 2.0 * M_PI / n;
        const double turnedA = a * std::cos(angle) - b * std::sin(angle);
        double turnedB = a * std::sin(angle) + b * std::cos(angle);
        if (sector & 1) turnedB = -turnedB;
        p.xyz[i] = turnedA;
        p.xyz[j] = turnedB;
    }
};

}  // namespace fraktal::blocks
