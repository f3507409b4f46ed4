#pragma once
#include <algorithm>

#include "core/block.hpp"

namespace fraktal::blocks {

// dIFS: distance-estimated IFS (knighty's "mdifs", fractalforums.com 2012; Mandelbulber2's dIFS
// formulas and transf_difs_* transforms). The orbit is an IFS that folds and scales space, and at
// chosen steps a shape step measures the distance from the orbit's point to a simple shape in
// the orbit's own frame; divided by the running derivative there, that is a distance in the
// starting space. The estimate is the least of them over the orbit (P4::orbitDistance), which
// the `difs` estimator returns: the object is the union of the shape's images.
//
// A shape step leaves the point as it is (a Global identity). Its divisor is
// |p.w| w_scale + w_offset: 1 and 0 divide by the running derivative itself; Mandelbulber2's
// transforms divide by DE + 1 (w_offset 1), and its dIFS formulas measure the shape at the point
// before their step and divide by the derivative after it, DE s + 1 for a scale s (w_scale s,
// w_offset 1). With w_vary the scale is the varying one, |p.w| |w_scale + a| + w_offset, a the
// orbit's offset before its scale_vary step moves it (formulas/scale_vary.hpp). A divisor below
// the running derivative overestimates the distance; `fraktal check` measures the stack either way.

// The least distance so far, lowered by a shape at distance d (the shape steps' shared tail).
// Mirrors difsDivisor() in shaders/formula.glsl.
inline double difsDivisor(const P4& p, double wScale, double wOffset, double wVary) {
    return std::abs(p.w) * std::abs(wScale + (wVary > 0.5 ? p.varyScale : 0.0)) + wOffset;
}
inline void recordShapeDistance(P4& p, double d, double wScale, double wOffset, double wVary) {
    p.orbitDistance = std::min(p.orbitDistance, d / difsDivisor(p, wScale, wOffset, wVary));
}
// The divisor's two parameters, the last of every shape step's.
inline constexpr ParamDecl kDifsWScale{
    "w_scale", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 16.0, "The running derivative's multiple in the divisor."};
inline constexpr ParamDecl kDifsWOffset{"w_offset",
                                        ParamType::Float,
                                        {0.0, 0.0, 0.0},
                                        0.0,
                                        16.0,
                                        "Added to the divisor (Mandelbulber2's dIFS transforms: 1)."};
inline constexpr ParamDecl kDifsWVary = toggleParam(
    "w_vary", false, "On: w_scale plus the orbit's varying scale offset (scale_vary), as the step's scale varies.");

// What every shape step declares alike: a Global identity in the "dIFS shapes" menu.
struct DifsShapeStep {
    static constexpr std::string_view menuGroup = "dIFS shapes";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr bool difsShape = true;
};

// The torus about z: the ring of radius R, the tube of radius `thickness` about it.
struct DifsTorus : DifsShapeStep {
    static constexpr std::string_view id = "difs_torus";
    static constexpr std::string_view label = "dIFS torus";
    static constexpr std::string_view help =
        "Measures the distance to a torus about z (ring radius, tube thickness) for the dIFS estimate; the point "
        "is left as it is.";
    static constexpr std::array params{
        ParamDecl{"ring_radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "Radius of the ring about z."},
        ParamDecl{"thickness", ParamType::Float, {0.1, 0.0, 0.0}, 0.0, 10.0, "Radius of the tube about the ring."},
        kDifsWScale,
        kDifsWOffset,
        kDifsWVary,
    };

    static constexpr std::string_view glsl = R"(
    float d = length(vec2(length(p.xy) - ring_radius, p.z)) - thickness;
    orbitDistance = min(orbitDistance, d / difsDivisor(p.w, w_scale, w_offset, w_vary));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double ring_radius = a.f(0), thickness = a.f(1);
        const double d = length(glm::dvec2(length(glm::dvec2(p.xyz.x, p.xyz.y)) - ring_radius, p.xyz.z)) - thickness;
        recordShapeDistance(p, d, a.f(2), a.f(3), a.f(4));
    }
};

// The box of half-sizes `size` about the origin: the distance outside it (0 within). Its x and y
// half-sizes may follow the point's z, as Mandelbulber2's dIFS box (DIFSBoxV1Iteration,
// DIFSBoxDiagonalV1Iteration of 2.20) lets them: plus `curve` z^2 (its curved sides, option T) and
// less `pyramid` z (its pyramid, option M). The distance is then Mandelbulber2's, the box's at the
// point's own height, not the true distance to the curved solid.
struct DifsBox : DifsShapeStep {
    static constexpr std::string_view id = "difs_box";
    static constexpr std::string_view label = "dIFS box";
    static constexpr std::string_view help =
        "Measures the distance to a box about the origin (half-sizes) for the dIFS estimate; the point is left as "
        "it is. Curve and pyramid widen x and y by curve z^2 and narrow them by pyramid z.";
    static constexpr std::array params{
        ParamDecl{"size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 10.0, "Half-sizes along x, y and z."},
        kDifsWScale,
        kDifsWOffset,
        kDifsWVary,
        ParamDecl{
            "curve", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Added to the x and y half-sizes times z^2."},
        ParamDecl{
            "pyramid", ParamType::Float, {0.0, 0.0, 0.0}, -10.0, 10.0, "Taken from the x and y half-sizes times z."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 half_size = size + vec3(vec2(curve * p.z * p.z - pyramid * p.z), 0.0);
    float d = length(max(abs(p.xyz) - half_size, vec3(0.0)));
    orbitDistance = min(orbitDistance, d / difsDivisor(p.w, w_scale, w_offset, w_vary));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double widen = a.f(4) * p.xyz.z * p.xyz.z - a.f(5) * p.xyz.z;
        const vec3 size = a.v3(0) + vec3(widen, widen, 0.0);
        const double d = length(max(abs(p.xyz) - size, vec3(0.0)));
        recordShapeDistance(p, d, a.f(1), a.f(2), a.f(3));
    }
};

// The ellipsoid of radii `radii` about the origin, by Inigo Quilez's bound
// |p/r| (|p/r| - 1) / |p/r^2| (iquilezles.org, "distance functions").
struct DifsEllipsoid : DifsShapeStep {
    static constexpr std::string_view id = "difs_ellipsoid";
    static constexpr std::string_view label = "dIFS ellipsoid";
    static constexpr std::string_view help =
        "Measures the distance to an ellipsoid about the origin (radii) for the dIFS estimate; the point is left "
        "as it is.";
    static constexpr std::array params{
        ParamDecl{"radii", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.01, 10.0, "Radii along x, y and z."},
        kDifsWScale,
        kDifsWOffset,
        kDifsWVary,
    };

    static constexpr std::string_view glsl = R"(
    float k0 = length(p.xyz / radii), k1 = length(p.xyz / (radii * radii));
    float d = k1 > 0.0 ? k0 * (k0 - 1.0) / k1 : -min(radii.x, min(radii.y, radii.z));
    orbitDistance = min(orbitDistance, d / difsDivisor(p.w, w_scale, w_offset, w_vary));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 radii = a.v3(0);
        const double k0 = length(p.xyz / radii), k1 = length(p.xyz / (radii * radii));
        const double d = k1 > 0.0 ? k0 * (k0 - 1.0) / k1 : -min(radii.x, min(radii.y, radii.z));
        recordShapeDistance(p, d, a.f(1), a.f(2), a.f(3));
    }
};

// The grids' bars: their section and the squeeze of z, the same for both.
inline constexpr ParamDecl kGridThickness{"thickness", ParamType::Float,      {0.005, 0.0, 0.0}, 0.0,
                                          1.0,         "Radius of each line."};
inline constexpr ParamDecl kGridZScale{"z_scale", ParamType::Float,           {1.0, 0.0, 0.0}, 0.01,
                                       10.0,      "z is divided by it first."};
inline constexpr ParamDecl kGridSquareBars =
    toggleParam("square_bars", false, "On: bars of square section (the larger of the two offsets).");
// A bar's distance from its offset `across` the grid and its height z, as the grids measure it.
inline double gridBarDistance(double across, double z, double thickness, bool squareBars) {
    return (squareBars ? std::max(std::abs(across), std::abs(z)) : length(glm::dvec2(across, z))) - thickness;
}

// A square grid of lines in the plane z = 0, `cell` apart along x and y, each line a tube of
// radius `thickness` (or a square bar, `square_bars`), z first divided by `z_scale`
// (Mandelbulber2's transf_difs_grid).
struct DifsGrid : DifsShapeStep {
    static constexpr std::string_view id = "difs_grid";
    static constexpr std::string_view label = "dIFS square grid";
    static constexpr std::string_view help =
        "Measures the distance to a square grid of bars in the plane z = 0 for the dIFS estimate; the point is "
        "left as it is.";
    static constexpr std::array params{
        ParamDecl{"cell", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Spacing of the lines along x and y."},
        kGridThickness,
        kGridZScale,
        kGridSquareBars,
        kDifsWScale,
        kDifsWOffset,
        kDifsWVary,
    };

    static constexpr std::string_view glsl = R"(
    float z = p.z / z_scale;
    vec2 offCell = abs(p.xy - cell * floor(p.xy / cell + 0.5));
    float across = min(offCell.x, offCell.y);
    float d = (square_bars > 0.5 ? max(across, abs(z)) : length(vec2(across, z))) - thickness;
    orbitDistance = min(orbitDistance, d / difsDivisor(p.w, w_scale, w_offset, w_vary));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double cell = a.f(0), thickness = a.f(1), z_scale = a.f(2), square_bars = a.f(3);
        const double z = p.xyz.z / z_scale;
        const glm::dvec2 xy(p.xyz.x, p.xyz.y);
        const glm::dvec2 offCell = glm::abs(xy - cell * glm::floor(xy / cell + 0.5));
        const double across = std::min(offCell.x, offCell.y);
        recordShapeDistance(p, gridBarDistance(across, z, thickness, square_bars > 0.5), a.f(4), a.f(5), a.f(6));
    }
};

// A hexagonal grid of lines in the plane z = 0 (cells `cell` across flats), as the square grid
// (Mandelbulber2's transf_difs_hextgrid2).
struct DifsHexGrid : DifsShapeStep {
    static constexpr std::string_view id = "difs_hex_grid";
    static constexpr std::string_view label = "dIFS hexagonal grid";
    static constexpr std::string_view help =
        "Measures the distance to a hexagonal grid of bars in the plane z = 0 for the dIFS estimate; the point is "
        "left as it is.";
    static constexpr std::array params{
        ParamDecl{"cell", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Size of the cells."},
        kGridThickness,
        kGridZScale,
        kGridSquareBars,
        kDifsWScale,
        kDifsWOffset,
        kDifsWVary,
    };

    static constexpr std::string_view glsl = R"(
    const float cos30 = 0.866025403784439, sin30 = 0.5;
    float z = p.z / z_scale;
    float offY = abs(p.y - cell * floor(p.y / cell + 0.5));
    float offX = abs(p.x - cell * 1.5 / cos30 * floor(p.x / cell / 1.5 * cos30 + 0.5));
    float across = min(max(offY, offX * cos30 + offY * sin30) - cell * 0.5, offY);
    float d = (square_bars > 0.5 ? max(abs(across), abs(z)) : length(vec2(across, z))) - thickness;
    orbitDistance = min(orbitDistance, d / difsDivisor(p.w, w_scale, w_offset, w_vary));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double cell = a.f(0), thickness = a.f(1), z_scale = a.f(2), square_bars = a.f(3);
        const double cos30 = 0.866025403784439, sin30 = 0.5;
        const double z = p.xyz.z / z_scale;
        const double offY = std::abs(p.xyz.y - cell * std::floor(p.xyz.y / cell + 0.5));
        const double offX = std::abs(p.xyz.x - cell * 1.5 / cos30 * std::floor(p.xyz.x / cell / 1.5 * cos30 + 0.5));
        const double across = std::min(std::max(offY, offX * cos30 + offY * sin30) - cell * 0.5, offY);
        recordShapeDistance(p, gridBarDistance(across, z, thickness, square_bars > 0.5), a.f(4), a.f(5), a.f(6));
    }
};

// The capped cylinder about z of Mandelbulber2's difs_cylinder (DIFSCylinderIteration in
// fractal_formulas.cpp): radius `radius`, half-height `height`, its radius growing by `cone` times
// |z| (a cone), its edges rounded by `round`. Mandelbulber2's options as toggles: x and z
// exchanged first, z signed in the cone's growth (not |z|), z squared there, flat tops (the cone
// left out of the caps) and rings (the distance to the rim rather than to the solid).
struct DifsCylinder : DifsShapeStep {
    static constexpr std::string_view id = "difs_cylinder";
    static constexpr std::string_view label = "dIFS cylinder";
    static constexpr std::string_view help =
        "Measures the distance to a capped cylinder (or cone) about z for the dIFS estimate; the point is left "
        "as it is.";
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 10.0, "Radius at z = 0."},
        ParamDecl{"height", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 20.0, "Half-height: the caps at z = +-height."},
        ParamDecl{"cone", ParamType::Float, {0.0, 0.0, 0.0}, -5.0, 5.0, "The radius shrinks by cone times |z|."},
        ParamDecl{"round", ParamType::Float, {0.0, 0.0, 0.0}, -5.0, 5.0, "Taken off inside the solid: rounds it."},
        toggleParam("swap_xz", false, "On: x and z exchanged first (a cylinder about x)."),
        toggleParam("signed_z", false, "On: the cone grows with z, not |z|."),
        toggleParam("squared_z", false, "On: the cone grows with z squared."),
        toggleParam("flat_tops", false, "On: the caps measured from the axis, without the cone."),
        toggleParam("rings", false, "On: the distance to the rim of the solid's section."),
        kDifsWScale,
        kDifsWOffset,
        kDifsWVary,
    };

    static constexpr std::string_view glsl = R"(
    vec3 q = swap_xz > 0.5 ? p.zyx : p.xyz;
    float radial = length(q.xy);
    float h = abs(q.z);
    float capped = h - height;
    if (signed_z > 0.5) h = q.z;
    if (squared_z > 0.5) h *= h;
    float side = radial - radius + cone * h;
    float d = length(vec2(max(flat_tops > 0.5 ? radial : side, 0.0), max(capped, 0.0)));
    if (rings > 0.5) d = length(vec2(side, capped));
    d += min(max(side, capped) - round, 0.0);
    orbitDistance = min(orbitDistance, d / difsDivisor(p.w, w_scale, w_offset, w_vary));
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double radius = a.f(0), height = a.f(1), cone = a.f(2), round = a.f(3);
        const double swap_xz = a.f(4), signed_z = a.f(5), squared_z = a.f(6), flat_tops = a.f(7), rings = a.f(8);
        vec3 q = swap_xz > 0.5 ? vec3(p.xyz.z, p.xyz.y, p.xyz.x) : p.xyz;
        double radial = length(glm::dvec2(q.x, q.y));
        double h = abs(q.z);
        double capped = h - height;
        if (signed_z > 0.5) h = q.z;
        if (squared_z > 0.5) h *= h;
        double side = radial - radius + cone * h;
        double d = length(glm::dvec2(max(flat_tops > 0.5 ? radial : side, 0.0), max(capped, 0.0)));
        if (rings > 0.5) d = length(glm::dvec2(side, capped));
        d += min(max(side, capped) - round, 0.0);
        recordShapeDistance(p, d, a.f(9), a.f(10), a.f(11));
    }
};

// The dIFS estimate: the least shape distance along the orbit (P4::orbitDistance), 1000 where no
// shape step ran. Negative inside a shape.
struct DifsEstimator {
    static constexpr std::string_view id = "difs";
    static constexpr std::string_view menuGroup = "dIFS shapes";
    static constexpr std::string_view label = "dIFS (least shape distance)";
    static constexpr std::string_view help =
        "The least of the distances the dIFS shape steps measured along the orbit, each over its running "
        "derivative: the union of the shape's images.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array<ParamDecl, 0> params{};

    static constexpr std::string_view glsl = R"(
    return orbitDistance;
)";
    static double estimate(const P4& p, const vec3&, Args) { return p.orbitDistance; }
};

}  // namespace fraktal::blocks
