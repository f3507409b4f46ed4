#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// msltoe's donut (Mandelbulber2's msltoe_donut, fractal_formulas.cpp MsltoeDonutIteration): the
// ring of radius R about z is cut into `sections` sectors; outside a thin tube about the ring
// (t = (R - rho)^2 + z^2 - thickness^2 > 0.03) the point's sector is turned onto +x, the sector's
// ring point moved to the origin, and the result scaled by `factor` with y and z swapped (each
// sector's piece of the ring holds the whole again); inside the tube it is divided by t. Mandelbulber2 estimates its
// distance by differences (escape_linear_gradient); the running derivative here bounds the step's Jacobian, |factor|
// outside the tube and, for v / t inside, 1 / |t| + |v| |grad t| / t^2 with |grad t| = 2 sqrt(t + thickness^2). The map
// jumps between sectors and at the tube's edge.
struct MsltoeDonut {
    static constexpr std::string_view id = "msltoe_donut";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe donut";
    static constexpr std::string_view help =
        "Rings of rings: each sector of the ring about z is moved to the centre and scaled; inside a thin tube, "
        "divided by t.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps between the ring's sectors and at the tube's edge";
    static constexpr std::array params{
        ParamDecl{"ring_radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.01, 10.0, "Radius R of the ring about z."},
        ParamDecl{"thickness", ParamType::Float, {0.1, 0.0, 0.0}, 0.0, 4.0, "Radius of the tube about the ring."},
        ParamDecl{"sections", ParamType::Float, {9.0, 0.0, 0.0}, 1.0, 64.0, "Sectors the ring is cut into."},
        ParamDecl{"factor", ParamType::Float, {3.0, 0.0, 0.0}, -10.0, 10.0, "Scale of each sector's copy."},
    };

    static constexpr std::string_view glsl = R"(
    float sector = 6.28318530717959 / sections;
    float rho = length(p.xy), toRing = ring_radius - rho;
    float t = toRing * toRing + p.z * p.z - thickness * thickness;
    float turn = p.x == 0.0 && p.y == 0.0 ? 0.0 : sector * floor(atan(p.y, p.x) / sector + 0.5);
    if (t > 0.03) {
        float c1 = cos(turn), s1 = sin(turn);
        vec3 v = vec3(c1 * p.x + s1 * p.y - ring_radius, -s1 * p.x + c1 * p.y, p.z);
        p.xyz = factor * v.xzy;
        p.w *= abs(factor);
    } else {
        float grad = 2.0 * sqrt(max(t + thickness * thickness, 0.0));
        p.w *= 1.0 / abs(t) + length(p.xyz) * grad / (t * t);
        p.xyz /= t;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double ring_radius = a.f(0), thickness = a.f(1), sections = a.f(2), factor = a.f(3);
        double sector = 6.28318530717959 / sections;
        double rho = std::hypot(p.xyz.x, p.xyz.y), toRing = ring_radius - rho;
        double t = toRing * toRing + p.xyz.z * p.xyz.z - thickness * thickness;
        double turn =
            p.xyz.x == 0.0 && p.xyz.y == 0.0 ? 0.0 : sector * floor(std::atan2(p.xyz.y, p.xyz.x) / sector + 0.5);
        if (t > 0.03) {
            double c1 = cos(turn), s1 = sin(turn);
            vec3 v = vec3(c1 * p.xyz.x + s1 * p.xyz.y - ring_radius, -s1 * p.xyz.x + c1 * p.xyz.y, p.xyz.z);
            p.xyz = factor * vec3(v.x, v.z, v.y);
            p.w *= abs(factor);
        } else {
            double grad = 2.0 * std::sqrt(std::max(t + thickness * thickness, 0.0));
            p.w *= 1.0 / abs(t) + length(p.xyz) * grad / (t * t);
            p.xyz /= t;
        }
    }
};

// The closing step of msltoe's sym2 and sym3 family: v pulled `offset` towards the origin
// (v (1 - offset / |v|), Mandelbulber2's z *= 1 + offset / -|z|), then scaled.
inline vec3 pulledAndScaled(const vec3& v, double offset, double scale) {
    return v * (1.0 - offset / std::max(length(v), 1e-30)) * scale;
}

// The family's shared parameters: the triplex's y factor, the constant added after the power, and
// the pull and scale of pulledAndScaled.
inline constexpr ParamDecl kTriplexYScale{
    "y_scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Multiplies the triplex's y term."};
inline constexpr ParamDecl kAddAfterPower{"add", ParamType::Vec3, {0.0, 0.0, 0.0}, -4.0, 4.0, "Added after the power."};
inline constexpr ParamDecl kPullOffset{
    "offset", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "Pulls the point this far towards 0."};
inline constexpr ParamDecl kPullScale{"scale", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "Scales the result."};

// msltoe's sym2 mod (Mandelbulber2's msltoe_sym2_mod, from Mandelbulb3D; fractalforums.com
// "choosing the squaring formula by location"): y and z swapped where |y| < |z|, x negated where
// then y > z, White's power-2 triplex with the xy term times y_scale, plus `add`, then pulled
// towards the origin by `offset` (v (1 - offset / |v|)) and scaled by `scale`. The running
// derivative is Mandelbulber2's 2 r |scale|; the swaps make the map jump.
struct MsltoeSym2Mod {
    static constexpr std::string_view id = "msltoe_sym2_mod";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe sym2 mod";
    static constexpr std::string_view help =
        "Power 2 triplex whose squaring depends on the octant (y, z swapped, x negated), plus add, pulled in by "
        "offset, scaled.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where it swaps y and z (|y| = |z|) and negates x";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        kTriplexYScale,
        kAddAfterPower,
        kPullOffset,
        kPullScale,
    };

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz) * abs(scale);
    vec3 v = abs(p.y) < abs(p.z) ? p.xzy : p.xyz;
    if (v.y > v.z) v.x = -v.x;
    vec3 v2 = v * v;
    float zr = 1.0 - v2.z / max(v2.x + v2.y + v2.z, 1e-30);
    v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * sqrt(v2.x + v2.y)) + add;
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double y_scale = a.f(0), offset = a.f(2), scale = a.f(3);
        const vec3 add = a.v3(1);
        p.w *= 2.0 * length(p.xyz) * abs(scale);
        vec3 v = abs(p.xyz.y) < abs(p.xyz.z) ? vec3(p.xyz.x, p.xyz.z, p.xyz.y) : p.xyz;
        if (v.y > v.z) v.x = -v.x;
        vec3 v2 = v * v;
        double zr = 1.0 - v2.z / std::max(v2.x + v2.y + v2.z, 1e-30);
        v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * std::sqrt(v2.x + v2.y)) + add;
        p.xyz = pulledAndScaled(v, offset, scale);
    }
};

// eiffie's variant of msltoe's Julia bulb (Mandelbulber2's eiffie_msltoe): the (y, z) plane folded
// into the sector |psi| <= pi / 8 about +y (psi = |mod(atan2(z, y) + 9 pi / 8, pi / 4) - pi / 8|),
// then the sym2 mod's power, add, pull and scale (without its octant swap). The running
// derivative is Mandelbulber2's 2 r |scale|; the sector fold is continuous, the power's latitude
// is not bounded by it.
struct EiffieMsltoe {
    static constexpr std::string_view id = "eiffie_msltoe";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "eiffie msltoe";
    static constexpr std::string_view help =
        "(y, z) folded into a pi/4 sector about +y, then the power 2 triplex plus add, pulled in by offset, scaled.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::Local;
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params = MsltoeSym2Mod::params;

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz) * abs(scale);
    float psi = abs(mod(atan(p.z, p.y) + 3.53429173528852, 0.785398163397448) - 0.392699081698724);
    float yz = length(p.yz);
    vec3 v = vec3(p.x, cos(psi) * yz, sin(psi) * yz);
    vec3 v2 = v * v;
    float zr = 1.0 - v2.z / max(v2.x + v2.y + v2.z, 1e-30);
    v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * sqrt(v2.x + v2.y)) + add;
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double y_scale = a.f(0), offset = a.f(2), scale = a.f(3);
        const vec3 add = a.v3(1);
        p.w *= 2.0 * length(p.xyz) * abs(scale);
        double psi =
            abs(glm::mod(std::atan2(p.xyz.z, p.xyz.y) + 3.53429173528852, 0.785398163397448) - 0.392699081698724);
        double yz = std::hypot(p.xyz.y, p.xyz.z);
        vec3 v = vec3(p.xyz.x, cos(psi) * yz, sin(psi) * yz);
        vec3 v2 = v * v;
        double zr = 1.0 - v2.z / std::max(v2.x + v2.y + v2.z, 1e-30);
        v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * std::sqrt(v2.x + v2.y)) + add;
        p.xyz = pulledAndScaled(v, offset, scale);
    }
};

// msltoe's sym3 mod (Mandelbulber2's msltoe_sym3_mod; with `sector` its msltoe_sym3_mod3, from
// fractalforums.com "choosing the squaring formula by location"). Without `sector`: y and z
// swapped where |y| < |z|, x and z negated where then y > z. With `sector`: the (y, z) plane turned
// by k pi / 4, k the whole eighths of a turn that bring atan2(z, y) + 2 pi under pi / 8 (as
// Mandelbulber2's loop counts them), and turned back after the power. The power is White's
// power-2 triplex whose latitude term divides by r^2 + stretch^2 y^2 z^2, its xy term times
// y_scale; then `add`, the pull towards the origin by `offset` and the scale, as in the sym2 mod.
// The running derivative is Mandelbulber2's 2 r |scale|.
struct MsltoeSym3Mod {
    static constexpr std::string_view id = "msltoe_sym3_mod";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe sym3 mod";
    static constexpr std::string_view help =
        "Power 2 triplex after an octant swap (or an eighth-turn sector turn), its latitude term stretched, plus "
        "add, pulled in by offset, scaled.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump =
        "its map jumps where it swaps y and z (|y| = |z|) and negates x and z, or at the sector edges";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        kTriplexYScale,
        kAddAfterPower,
        kPullOffset,
        kPullScale,
        ParamDecl{"stretch", ParamType::Float, {0.0, 0.0, 0.0}, -4.0, 4.0, "Its square times y^2 z^2 joins r^2."},
        toggleParam("sector", false, "On: turn (y, z) into an eighth-turn sector (mod3) in place of the octant swap."),
    };

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz) * abs(scale);
    vec3 v = p.xyz;
    float turn = 0.0;
    if (sector > 0.5) {
        float psi = atan(v.z, v.y) + 6.28318530717959;
        turn = -0.785398163397448 * max(ceil((psi - 0.392699081698724) / 0.785398163397448), 0.0);
        v.yz = vec2(v.y * cos(turn) - v.z * sin(turn), v.y * sin(turn) + v.z * cos(turn));
    } else {
        if (abs(v.y) < abs(v.z)) v = v.xzy;
        if (v.y > v.z) v.xz = -v.xz;
    }
    vec3 v2 = v * v;
    float zr = 1.0 - v2.z / max(v2.x + v2.y + v2.z + stretch * stretch * v2.y * v2.z, 1e-30);
    v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * sqrt(v2.x + v2.y));
    v.yz = vec2(v.y * cos(turn) + v.z * sin(turn), -v.y * sin(turn) + v.z * cos(turn));
    v += add;
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double y_scale = a.f(0), offset = a.f(2), scale = a.f(3), stretch = a.f(4);
        const vec3 add = a.v3(1);
        p.w *= 2.0 * length(p.xyz) * abs(scale);
        vec3 v = p.xyz;
        double turn = 0.0;
        if (a.f(5) > 0.5) {
            const double psi = std::atan2(v.z, v.y) + 6.28318530717959;
            turn = -0.785398163397448 * std::max(std::ceil((psi - 0.392699081698724) / 0.785398163397448), 0.0);
            v = vec3(v.x, v.y * cos(turn) - v.z * sin(turn), v.y * sin(turn) + v.z * cos(turn));
        } else {
            if (abs(v.y) < abs(v.z)) v = vec3(v.x, v.z, v.y);
            if (v.y > v.z) v = vec3(-v.x, v.y, -v.z);
        }
        const vec3 v2 = v * v;
        const double zr = 1.0 - v2.z / std::max(v2.x + v2.y + v2.z + stretch * stretch * v2.y * v2.z, 1e-30);
        v = vec3((v2.x - v2.y) * zr, 2.0 * v.x * v.y * zr * y_scale, 2.0 * v.z * std::sqrt(v2.x + v2.y));
        v = vec3(v.x, v.y * cos(turn) + v.z * sin(turn), -v.y * sin(turn) + v.z * cos(turn)) + add;
        p.xyz = pulledAndScaled(v, offset, scale);
    }
};

// msltoe's Julia bulb mod 2 (Mandelbulber2's msltoe_sym3_mod2; same thread): where z^2 < y^2 the
// azimuth atan2(y, x) and the latitude asin(z / r') doubled, r' = (r^2 + stretch y^2 z^2)^(1/2),
// into (cos theta cos phi, sin theta cos phi, -sin phi) r^2; elsewhere the same in the xz plane with
// y as the latitude, (cos theta cos phi, -sin phi, sin theta cos phi) r^2. Then `add`, the pull by
// `offset` and the scale. The doubled angles' cosines and sines are written without trigonometry
// (cos 2a = 1 - 2 sin^2 a, sin 2a = 2 sin a cos a): the GPU's asin and atan are not correctly
// rounded, and an error of 1e-3 decided the next iteration's chart differently near y^2 = z^2.
// The running derivative is Mandelbulber2's 2 r |scale|.
struct MsltoeSym3Mod2 {
    static constexpr std::string_view id = "msltoe_sym3_mod2";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe sym3 mod2";
    static constexpr std::string_view help =
        "Power 2 bulb whose angles are measured about z or about y, whichever the point is nearer, plus add, pulled "
        "in by offset, scaled.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where it changes the axis its angles are measured about";
    static constexpr Degree degree{{}, 2.0};
    static constexpr std::array params{
        ParamDecl{"stretch", ParamType::Float, {0.0, 0.0, 0.0}, 0.0, 4.0, "Times y^2 z^2, joins r^2 in the latitude."},
        kAddAfterPower,
        kPullOffset,
        kPullScale,
    };

    static constexpr std::string_view glsl = R"(
    p.w *= 2.0 * length(p.xyz) * abs(scale);
    vec3 v2 = p.xyz * p.xyz;
    float rr = v2.x + v2.y + v2.z;
    float r1 = max(sqrt(max(rr + stretch * v2.y * v2.z, 0.0)), 1e-30);
    bool aboutZ = v2.z < v2.y;
    float u = aboutZ ? p.y : p.z;
    float rho2 = v2.x + u * u;
    vec2 theta = rho2 > 0.0 ? vec2(v2.x - u * u, 2.0 * p.x * u) / rho2 : vec2(1.0, 0.0);
    float s = clamp((aboutZ ? p.z : p.y) / r1, -1.0, 1.0);
    vec2 phi = vec2(1.0 - 2.0 * s * s, 2.0 * s * sqrt(1.0 - s * s));
    vec3 v = rr * (aboutZ ? vec3(theta.x * phi.x, theta.y * phi.x, -phi.y)
                          : vec3(theta.x * phi.x, -phi.y, theta.y * phi.x)) + add;
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double stretch = a.f(0), offset = a.f(2), scale = a.f(3);
        const vec3 add = a.v3(1);
        p.w *= 2.0 * length(p.xyz) * abs(scale);
        const vec3 v2 = p.xyz * p.xyz;
        const double rr = v2.x + v2.y + v2.z;
        const double r1 = std::max(std::sqrt(std::max(rr + stretch * v2.y * v2.z, 0.0)), 1e-30);
        const bool aboutZ = v2.z < v2.y;
        const double u = aboutZ ? p.xyz.y : p.xyz.z, rho2 = v2.x + u * u;
        const glm::dvec2 theta = rho2 > 0.0 ? glm::dvec2(v2.x - u * u, 2.0 * p.xyz.x * u) / rho2 : glm::dvec2(1.0, 0.0);
        const double s = clamp((aboutZ ? p.xyz.z : p.xyz.y) / r1, -1.0, 1.0);
        const glm::dvec2 phi(1.0 - 2.0 * s * s, 2.0 * s * std::sqrt(1.0 - s * s));
        vec3 v = rr * (aboutZ ? vec3(theta.x * phi.x, theta.y * phi.x, -phi.y)
                              : vec3(theta.x * phi.x, -phi.y, theta.y * phi.x)) +
                 add;
        p.xyz = pulledAndScaled(v, offset, scale);
    }
};

// The fold of msltoe's sym4 mod (Mandelbulber2's msltoe_sym4_mod, from Mandelbulb3D): x and z
// swapped where |x| < |z| m.x, then x and y where |x| < |y| m.y, then y and z where |y| < |z| m.z
// (at m = 1 the coordinates sorted by size, the largest in x), then y and z negated where their
// sign differs from x's. A permutation and mirror per region keep distances; the map jumps where
// the swaps and signs change.
struct MsltoeSym4Fold {
    static constexpr std::string_view id = "msltoe_sym4_fold";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe sym4 fold";
    static constexpr std::string_view help =
        "Swap the coordinates towards |x| >= |y| >= |z| (each test weighted), then give y and z the sign of x.";
    static constexpr Category category = Category::Fold;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = "its map jumps where a swap or a sign changes";
    static constexpr std::array params{
        ParamDecl{"weights", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.0, 4.0, "Weigh the x-z, x-y and y-z swap tests."},
    };

    static constexpr std::string_view glsl = R"(
    if (abs(p.x) < abs(p.z) * weights.x) p.xz = p.zx;
    if (abs(p.x) < abs(p.y) * weights.y) p.xy = p.yx;
    if (abs(p.y) < abs(p.z) * weights.z) p.yz = p.zy;
    if (p.x * p.z < 0.0) p.z = -p.z;
    if (p.x * p.y < 0.0) p.y = -p.y;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const vec3 weights = a.v3(0);
        vec3& v = p.xyz;
        if (abs(v.x) < abs(v.z) * weights.x) std::swap(v.x, v.z);
        if (abs(v.x) < abs(v.y) * weights.y) std::swap(v.x, v.y);
        if (abs(v.y) < abs(v.z) * weights.z) std::swap(v.y, v.z);
        if (v.x * v.z < 0.0) v.z = -v.z;
        if (v.x * v.y < 0.0) v.y = -v.y;
    }
};

// msltoe's toroidal bulb (Mandelbulber2's msltoe_toroidal; fractalforums.com "toroidal
// coordinates"): the point measured from the nearest point of the ring of radius R about z, at
// squared distance d^2 and latitude phi = asin(z / d) there (atan2(z, its distance in the plane),
// which the GPU rounds better), with azimuth theta = atan2(y, x); then
// rp = (d^2)^radial_power, and the point becomes ((R + rp cos(m phi)) cos(n theta),
// (R + rp cos(m phi)) sin(n theta), -rp sin(m phi)), m the latitude and n the azimuth power; then the
// pull by `offset` and the scale, as in the sym2 mod. The running derivative is Mandelbulber2's
// rp (radial_power + 1) |scale|, an estimate the check measures against.
struct MsltoeToroidal {
    static constexpr std::string_view id = "msltoe_toroidal";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "msltoe toroidal bulb";
    static constexpr std::string_view help =
        "A bulb in toroidal coordinates about a ring: its distance raised, its latitude and azimuth multiplied.";
    static constexpr Category category = Category::Power;
    static constexpr DerivativeBound derivative = DerivativeBound::None;
    static constexpr std::string_view jump = kNonIntegerPowerSeam;
    static DerivativeBound derivativeFor(Args a) { return sphericalPowerBound(a.f(3)); }
    // |v'| grows as |v|^(2 radial_power); a degree names one parameter, so the potential estimate
    // reads half the growth (the import closes it with the log estimate, which needs none).
    static constexpr Degree degree{"radial_power"};
    static constexpr std::array params{
        ParamDecl{"ring_radius", ParamType::Float, {0.5, 0.0, 0.0}, 0.0, 8.0, "R: the ring's radius about z."},
        ParamDecl{"radial_power", ParamType::Float, {4.0, 0.0, 0.0}, 0.5, 16.0, "The squared distance's power."},
        ParamDecl{"latitude_power", ParamType::Float, {8.0, 0.0, 0.0}, -32.0, 32.0, "m: multiplies the latitude."},
        ParamDecl{"azimuth_power", ParamType::Float, {9.0, 0.0, 0.0}, -32.0, 32.0, "n: multiplies the azimuth."},
        kPullOffset,
        kPullScale,
    };

    static constexpr std::string_view glsl = R"(
    float theta = (p.x == 0.0 && p.y == 0.0) ? 0.0 : atan(p.y, p.x);
    vec2 ring = ring_radius * vec2(cos(theta), sin(theta));
    float planar = length(p.xy - ring);
    float d2 = max(planar * planar + p.z * p.z, 1e-30);
    float phi = ((planar == 0.0 && p.z == 0.0) ? 0.0 : atan(p.z, planar)) * latitude_power;
    float rp = pow(d2, radial_power);
    p.w *= rp * (radial_power + 1.0) * abs(scale);
    theta *= azimuth_power;
    float around = ring_radius + rp * cos(phi);
    vec3 v = vec3(around * cos(theta), around * sin(theta), -rp * sin(phi));
    float len = max(length(v), 1e-30);
    p.xyz = v * (1.0 - offset / len) * scale;
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double ring_radius = a.f(0), radial_power = a.f(1), latitude_power = a.f(2), azimuth_power = a.f(3),
                     offset = a.f(4), scale = a.f(5);
        double theta = std::atan2(p.xyz.y, p.xyz.x);
        const glm::dvec2 ring = ring_radius * glm::dvec2(cos(theta), sin(theta));
        const glm::dvec2 off = glm::dvec2(p.xyz.x, p.xyz.y) - ring;
        const double planar = length(off), d2 = std::max(planar * planar + p.xyz.z * p.xyz.z, 1e-30);
        const double phi = std::atan2(p.xyz.z, planar) * latitude_power;
        const double rp = std::pow(d2, radial_power);
        p.w *= rp * (radial_power + 1.0) * abs(scale);
        theta *= azimuth_power;
        const double around = ring_radius + rp * cos(phi);
        p.xyz = pulledAndScaled(vec3(around * cos(theta), around * sin(theta), -rp * sin(phi)), offset, scale);
    }
};

}  // namespace fraktal::blocks
