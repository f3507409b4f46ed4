// Closing estimators. IFS primitives divide the primitive's distance by the running scale (seed
// 3.2: "return the distance to the reference cube divided by the total scale applied"); the
// escape-time estimators use the running derivative (Hart et al. 1989; Syntopia part V).
#pragma once
#include <algorithm>

#include "core/block.hpp"

namespace fraktal::blocks {

struct BoxEstimator {
    static constexpr std::string_view id = "box";
    static constexpr std::string_view label = "Box";
    static constexpr std::string_view help = "Distance to a box of the given half-size, over the running scale.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"size", ParamType::Vec3, {1.0, 1.0, 1.0}, 0.001, 100.0, "Half-size of the box."},
    };

    static constexpr std::string_view glsl = R"(
    vec3 q = abs(p.xyz) - size;
    return (length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)) / abs(p.w);
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const vec3 size = a.v3(0);
        vec3 q = abs(p.xyz) - size;
        return (length(max(q, 0.0)) + min(max(q.x, max(q.y, q.z)), 0.0)) / abs(p.w);
    }
};

struct SphereEstimator {
    static constexpr std::string_view id = "sphere";
    static constexpr std::string_view label = "Sphere";
    static constexpr std::string_view help = "Distance to a sphere, over the running scale.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"radius", ParamType::Float, {1.0, 0.0, 0.0}, 0.0, 100.0, "Sphere radius."},
    };

    static constexpr std::string_view glsl = R"(
    return (length(p.xyz) - radius) / abs(p.w);
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double radius = a.f(0);
        return (length(p.xyz) - radius) / abs(p.w);
    }
};

// Regular tetrahedron with vertices (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1) times `size`:
// the largest signed distance to its four face planes (a lower bound of the true distance).
struct TetrahedronEstimator {
    static constexpr std::string_view id = "tetrahedron";
    static constexpr std::string_view label = "Tetrahedron";
    static constexpr std::string_view help = "Distance to a regular tetrahedron, over the running scale.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::Distance;
    static constexpr std::array params{
        ParamDecl{"size", ParamType::Float, {1.0, 0.0, 0.0}, 0.001, 100.0, "Vertex coordinate of the tetrahedron."},
    };

    static constexpr std::string_view glsl = R"(
    float md = max(max(-p.x - p.y - p.z, -p.x + p.y + p.z), max(p.x - p.y + p.z, p.x + p.y - p.z));
    return (md - size) / (sqrt(3.0) * abs(p.w));
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double size = a.f(0);
        const vec3 q = p.xyz;
        double md = max(max(-q.x - q.y - q.z, -q.x + q.y + q.z), max(q.x - q.y + q.z, q.x + q.y - q.z));
        return (md - size) / (std::sqrt(3.0) * abs(p.w));
    }
};

// The constant strings Parts joined, as a constant string: a twin's id, label and GLSL built
// from its original's.
template <const std::string_view&... Parts>
struct JoinedText {
    static constexpr auto chars = [] {
        std::array<char, (Parts.size() + ... + 0)> joined{};
        size_t at = 0;
        ((std::copy(Parts.begin(), Parts.end(), joined.begin() + at), at += Parts.size()), ...);
        return joined;
    }();
    static constexpr std::string_view value{chars.data(), chars.size()};
};

inline constexpr std::string_view kGradientTwinId = "_gradient";
inline constexpr std::string_view kGradientTwinLabel = " (gradient)";
inline constexpr std::string_view kGradientTwinHelp =
    " primitive over |grad| of its distance by differences of the orbit (four more orbits per estimate) instead of "
    "the running scale: tighter after twists and bends, five times the cost.";
// What stands in for the running derivative w in the original's body: |grad V| for a distance
// estimate (V the primitive's distance), r |grad log r| for an escape-time one (which divides by
// |w| / r). Without a gradient (0 or not a number) w stays.
inline constexpr std::string_view kGradientInWForEscape = R"(
    p.w = orbitGradient > 0.0 ? orbitGradient * length(p.xyz) : p.w;)";
inline constexpr std::string_view kGradientInWForDistance = R"(
    p.w = orbitGradient > 0.0 ? orbitGradient : abs(p.w);)";
template <Membership M>
inline constexpr std::string_view kGradientInW =
    M == Membership::EscapeTime ? kGradientInWForEscape : kGradientInWForDistance;

// An estimator's gradient twin: the original estimate with |grad| of the composed map's orbit
// value (P4::orbitGradient, tetrahedral differences of the orbit: four more orbits) in place of
// the running derivative w. w multiplies each step's largest stretch, and where the stretched
// direction turns from step to step (twists, bends, folds between them) the product outgrows the
// composed map's own. For a primitive that is the first-order distance |f| / |grad f| to the zero
// set of f (Taubin, "Distance approximations for rasterizing implicit curves", 1994). No bound:
// the gradient jumps across folds and jumps, and where one lies within the difference step the
// difference is none, so the factor is measured. The original's own body runs with the gradient
// in p.w, in GLSL and C++ alike. The id, label and help are the primitive's with "gradient"; an
// escape-time twin names its own (EscapeGradientEstimator).
template <class Original>
struct GradientTwin {
    static constexpr bool escapeTime = Original::membership == Membership::EscapeTime;
    static constexpr std::string_view id = JoinedText<Original::id, kGradientTwinId>::value;
    static constexpr std::string_view label = JoinedText<Original::label, kGradientTwinLabel>::value;
    static constexpr std::string_view help = JoinedText<Original::label, kGradientTwinHelp>::value;
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Original::membership;
    static constexpr std::string_view gradientOf = Original::id;
    static constexpr std::array params = Original::params;

    static constexpr std::string_view glsl = JoinedText<kGradientInW<Original::membership>, Original::glsl>::value;
    static double estimate(const P4& p, const vec3& c, Args a) {
        P4 q = p;
        if constexpr (escapeTime)
            q.w = p.orbitGradient > 0.0 ? p.orbitGradient * length(p.xyz) : p.w;
        else
            q.w = p.orbitGradient > 0.0 ? p.orbitGradient : abs(p.w);
        return Original::estimate(q, c, a);
    }
};

// (1 - e^-G) / G: the potential estimate's share of the log one. Below G = 0.1 its series to G^4
// (error under 2e-8): 1 - exp(-G) loses digits to cancellation in single precision, 1e-4 of them
// at G = 1e-3. The GLSL twin is in shaders/formula.glsl.
inline double potentialShare(double G) {
    return G < 0.1 ? 1.0 - G * (1.0 / 2.0 - G * (1.0 / 6.0 - G * (1.0 / 24.0 - G / 120.0))) : (1.0 - std::exp(-G)) / G;
}

// 0.5 log(r) r / dr: for power iterations (Mandelbulb), Hubbard-Douady potential. That is
// 0.5 G / |grad G| with the potential G = log(r) / D (D the power steps' degrees, P4::degree),
// and the bound is for the distance to the limit set, where G = 0. The surface a finite
// iteration count draws lies outside it, on the level set where the last iteration reaches the
// bailout, G = log(B) / (all iterations' degrees). Near that surface the uncorrected estimate
// measures the distance to the set inside it and overshoots: 2.6x for a single Bristorbrot step
// at 6 iterations (tests/safe_step_test.cpp's stacks). G minus the surface's potential is the
// Green's function of the filled level set, so the bound holds for it with log(r) replaced by
// log(r) - surfaceLogR (P4::surfaceLogR: the surface's log radius in this orbit's units; 0
// without power steps).
struct EscapeLogEstimator {
    static constexpr std::string_view id = "escape_log";
    static constexpr std::string_view label = "Escape time (log)";
    static constexpr std::string_view help =
        "0.5 log(r) r / dr, for power iterations such as the Mandelbulb; log r counted from the surface the "
        "iterations draw.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::EscapeTime;
    static constexpr std::array<ParamDecl, 0> params{};

    // With a bailout of 1 or more an escaped orbit has log(r) > 0. A negative estimate comes from
    // an orbit that stayed inside the unit ball, a point inside, where the running derivative may
    // have shrunk towards 0 and the quotient is no distance (down to -1.6e10 on the juliabulb's
    // grid; float and double differ there), and a hit refinement that steps by it (t += d - level)
    // would jump far back along the ray. Inside is 0, tested on r rather than on the quotient: an
    // orbit that collapsed to the origin (a power of r below 1 underflows to 0, and the power
    // block sets p.w to 0 there) gives log(0) * 0 / 0, not a number. An orbit inside the surface
    // (it did not escape) has log(r) <= surfaceLogR: 0 as well.
    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    return r > 1.0 ? 0.5 * max(log(r) - surfaceLogR, 0.0) * r / abs(p.w) : 0.0;
)";
    static double estimate(const P4& p, const vec3&, Args) {
        const double surfaceLogR = p.surfaceLogR;
        double r = length(p.xyz);
        return r > 1.0 ? 0.5 * max(std::log(r) - surfaceLogR, 0.0) * r / abs(p.w) : 0.0;
    }
};

// The log estimate with its far field corrected by the potential. An orbit that escaped with
// radius r after power steps of total degree D (P4::degree) has the potential G = log(r) / D,
// counted here, as in the log estimate, from the surface the iterations draw: G = (log(r) -
// surfaceLogR) / D, and the log estimate is 0.5 G / |grad G|. Where G is small (near the surface,
// and after many steps) that is the Hubbard-Douady bound; where it is not (a point that escaped
// after one or two steps) G / |grad G| outgrows the distance: for a power alone, whose drawn
// surface is the ball of radius rho = B^(1 / all iterations' degrees), the log estimate is
// 0.5 r log(r / rho) against r - rho. (1 - e^-G) / |grad G| is r - rho there at every r, and
// G / |grad G| as G goes to 0, so the estimate is the log one times q = (1 - e^-G) / G: equal at
// the surface, smaller far away, half the distance to the drawn ball everywhere. One step factor
// then fits near and far samples alike (tests/safe_step_test.cpp). q is potentialShare(G). A
// degree that overflowed gives G = 0 and q = 1.
struct EscapePotentialEstimator {
    static constexpr std::string_view id = "escape_potential";
    static constexpr std::string_view label = "Escape time (potential)";
    static constexpr std::string_view help =
        "The log estimate, 0.5 log(r) r / dr, times (1 - e^-G) / G with the potential G = log(r) / degree "
        "(both counted from the surface the iterations draw): tighter far from the object, for power iterations.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::EscapeTime;
    static constexpr std::array<ParamDecl, 0> params{};

    // Inside (r <= 1, or not a number) is 0, as for the log estimate.
    static constexpr std::string_view glsl = R"(
    float r = length(p.xyz);
    if (!(r > 1.0)) return 0.0;
    float fromSurface = max(log(r) - surfaceLogR, 0.0);
    float G = fromSurface / degree;
    float q = potentialShare(G);
    return 0.5 * q * fromSurface * r / abs(p.w);
)";
    static double estimate(const P4& p, const vec3&, Args) {
        const double degree = p.degree, surfaceLogR = p.surfaceLogR;
        double r = length(p.xyz);
        if (!(r > 1.0)) return 0.0;
        double fromSurface = max(std::log(r) - surfaceLogR, 0.0);
        double G = fromSurface / degree;
        double q = potentialShare(G);
        return 0.5 * q * fromSurface * r / abs(p.w);
    }
};

// The potential estimate with |grad log r| measured instead of bounded. The running derivative
// multiplies each step's largest stretch, an upper bound of the composed map's: where the stretched
// direction turns from step to step (twists, bends, the Bristorbrot, folds between them) the
// product outgrows the composed stretch and the estimate shrinks with it. The gradient of log r
// of the last point with respect to the starting point, by tetrahedral differences of the orbit
// run for the same iterations (P4::orbitGradient: four more orbits), is the composed map's own; with
// it 0.5 G / |grad G| is the Hubbard-Douady form itself (Hubbard and Douady; Syntopia, "Distance
// estimated 3D fractals" part V, and Mandelbulber's "delta DE", which takes the same
// differences). It is no bound either: where the map jumps within the difference step the
// difference is no derivative, so its factor is measured like the others'. GradientTwin runs the
// potential estimate's own body with r |grad log r| in p.w.
struct EscapeGradientEstimator : GradientTwin<EscapePotentialEstimator> {
    static constexpr std::string_view id = "escape_gradient";
    static constexpr std::string_view label = "Escape time (gradient)";
    static constexpr std::string_view help =
        "The potential estimate with |grad log r| from differences of the orbit (four more orbits per estimate) "
        "instead of the running derivative: tighter where twists, bends and folds turn the stretch from step to "
        "step, five times the cost.";
};

// r / |dr|: for fold-and-scale escape-time formulas (Mandelbox; Lowe, Syntopia part VI).
struct EscapeLinearEstimator {
    static constexpr std::string_view id = "escape_linear";
    static constexpr std::string_view label = "Escape time (linear)";
    static constexpr std::string_view help = "r / |dr|, for Mandelbox-type fold-and-scale formulas.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::EscapeTime;
    static constexpr std::array params{
        ParamDecl{"offset",
                  ParamType::Float,
                  {0.0, 0.0, 0.0},
                  0.0,
                  10.0,
                  "Subtracted from r (Mandelbulber's linear DE constant)."},
    };

    static constexpr std::string_view glsl = R"(
    return (length(vec4(p.xyz, pointW)) - offset) / abs(p.w);
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double offset = a.f(0);
        return (length(vec4(p.xyz, p.pointW)) - offset) / abs(p.w);
    }
};

// The linear estimate on the distance to the z axis, (r_xy - offset) / |dr|: Mandelbulber2's
// pseudo_kleinian_std_de takes r = (x^2 + y^2)^(1/2) after its step (compute_fractal.cpp), and its
// linear DE function divides that by the running derivative.
struct EscapeLinearXyEstimator {
    static constexpr std::string_view id = "escape_linear_xy";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Escape time (linear, xy)";
    static constexpr std::string_view help =
        "(r_xy - offset) / |dr| with r_xy the distance to the z axis (Mandelbulber2's pseudo-Kleinian std DE).";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::EscapeTime;
    static constexpr std::array params = EscapeLinearEstimator::params;

    static constexpr std::string_view glsl = R"(
    return (length(p.xy) - offset) / abs(p.w);
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double offset = a.f(0);
        return (std::hypot(p.xyz.x, p.xyz.y) - offset) / abs(p.w);
    }
};

// Mandelbulber2's delta DE for its linear formulas (calculate_distance.cpp): 0.5 (r - offset) /
// |grad r|, with |grad r| = r |grad log r| from differences of the orbit (P4::orbitGradient, as the
// escape gradient's) in place of the running derivative. Where a step's own factor misjudges its
// stretch (sector wraps, conditional divisions) the composed map's gradient is the better
// denominator. The half is Mandelbulber2's: at the same threshold the surface lies where the
// linear estimate is twice it (the step factor, measured, makes up the stride). No bound.
struct EscapeLinearGradientEstimator {
    static constexpr std::string_view id = "escape_linear_gradient";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Escape time (linear, gradient)";
    static constexpr std::string_view help =
        "0.5 r / |grad r| from differences of the orbit (four more orbits per estimate) instead of the running "
        "derivative: Mandelbulber2's delta DE for fold-and-scale formulas, five times the cost.";
    static constexpr Category category = Category::Estimator;
    static constexpr Membership membership = Membership::EscapeTime;
    static constexpr std::string_view gradientOf = EscapeLinearEstimator::id;
    // Mandelbulber2's convention, for the files that ask for it: the check does not offer it in
    // place of the linear estimate (a formula that chose it is measured with it).
    static constexpr bool offeredAsTwin = false;
    static constexpr std::array params = EscapeLinearEstimator::params;

    static constexpr std::string_view glsl = R"(
    p.w = orbitGradient > 0.0 ? orbitGradient * length(p.xyz) : p.w;
    return 0.5 * (length(p.xyz) - offset) / abs(p.w);
)";
    static double estimate(const P4& p, const vec3&, Args a) {
        const double offset = a.f(0);
        const double w = p.orbitGradient > 0.0 ? p.orbitGradient * length(p.xyz) : p.w;
        return 0.5 * (length(p.xyz) - offset) / abs(w);
    }
};

}  // namespace fraktal::blocks
