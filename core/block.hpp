// A block is one step of a distance-estimator formula: a fold, a transform, a power iteration or
// the closing estimator. Each block is declared once (formulas/*.hpp): its id, help text, one
// parameter list, its GLSL body and its CPU body side by side. That declaration drives GLSL
// emission, CPU evaluation, preset I/O, uniforms and the editor's widgets.
#pragma once

#include <array>
#include <concepts>
#include <span>
#include <string_view>

#include "core/vec.hpp"

namespace fraktal {

enum class Category { Fold, Transform, Power, Estimator };

std::string_view categoryName(Category c);

// Toggle: an on/off switch (a checkbox in the editor, true/false in a preset). It keeps 0 or 1 in
// x and reaches GLSL as a float uniform, so a body tests it as `name > 0.5` on both sides, and
// its range is 0..1.
enum class ParamType { Float, Vec3, Toggle };

// Kinds held in x alone and passed to GLSL as one float.
constexpr bool isScalar(ParamType t) { return t != ParamType::Vec3; }

// One parameter. Floats and toggles keep their value in x. The range is what the editor's widget
// offers and what a preset may hold (per component for vectors).
struct ParamDecl {
    std::string_view name;
    ParamType type = ParamType::Float;
    vec3 defaultValue{0.0};
    double min = 0.0;
    double max = 1.0;
    std::string_view help;
    bool direction = false;  // a vector used as a direction: must not be zero
    // The name the editor shows, in an artist's words; empty: the name above with its underscores
    // as spaces ("box_size": "Box size"). Presets keep using `name`.
    std::string_view label = {};

    // The same parameter shown as `text`: ParamDecl{...}.labelled("Trace, real part").
    constexpr ParamDecl labelled(std::string_view text) const {
        ParamDecl d = *this;
        d.label = text;
        return d;
    }
};

// An on/off parameter: 0 or 1 (`on`) in x, range 0..1.
constexpr ParamDecl toggleParam(std::string_view name, bool on, std::string_view help) {
    return ParamDecl{name, ParamType::Toggle, {on ? 1.0 : 0.0, 0.0, 0.0}, 0.0, 1.0, help};
}

using ParamValue = vec3;

// The parameter values of one node, in declaration order, as the CPU body reads them.
struct Args {
    const ParamValue* values;
    double f(int i) const { return values[i].x; }
    vec3 v3(int i) const { return values[i]; }
};

// How an estimator tells inside from outside, for the reference marcher and `fraktal check`.
enum class Membership {
    Distance,    // inside where the estimate is <= 0 (IFS primitives: box, sphere, tetrahedron)
    EscapeTime,  // inside where the orbit never passed the bailout (Mandelbulb, Mandelbox)
};

// How far the factor a step applies to the running derivative p.w bounds the step's stretch
// (its Jacobian's largest singular value). A primitive's distance over p.w is a proven lower
// bound of the distance to the object only when every step's bound is Global; otherwise it is
// an estimate whose step factor is measured with a margin (core/safe_step.hpp).
enum class DerivativeBound {
    // The same bound everywhere: isometries, reflection and clamp folds, uniform scales, adding
    // c. The map is continuous, so the bound holds between any two points.
    Global,
    // A bound at the point only: sphere folds, inversions, twist and bend, powers. A neighbour
    // whose orbit passes nearer a centre of inversion stretches more.
    Local,
    // The map jumps (wraps, conditional shifts): nothing bounds the distance across a jump.
    None,
};

// A spherical power's map is continuous where the power n is an integer; otherwise n phi jumps by
// 2 pi n (mod 2 pi) across the atan2 cut.
constexpr DerivativeBound sphericalPowerBound(double n) {
    return n == double(static_cast<long long>(n)) ? DerivativeBound::Local : DerivativeBound::None;
}
inline constexpr std::string_view kNonIntegerPowerSeam =
    "its map jumps across the atan2 seam when the power is not a whole number (n phi wraps by 2 pi n)";

// The degree a power step raises its input to (|F(v)| grows as |v|^n far from the origin), by
// the name of the parameter that holds it or as a number: the potential estimate
// (formulas/estimators.hpp) needs the product of the degrees an orbit went through. Steps that
// do not declare one have degree 1 (folds, scales and adding c leave the growth linear).
struct Degree {
    std::string_view param;
    double fixed = 1.0;
};

// The type-erased description that the rest of the program sees, for one family of blocks: the
// state a step transforms, the point `c` it sees and how its estimators decide membership. 3D
// blocks are BlockDesc below; 2D blocks (core/plane/plane_block.hpp) are the same template over
// the plane's state, so both families share one definition, one set of concepts and describe.
template <class StateT, class PointT, class MembershipT>
struct BlockDescOf {
    using State = StateT;
    using Point = PointT;
    using MembershipKind = MembershipT;
    using ApplyFn = void (*)(State& p, const Point& c, Args a);
    using EstimateFn = double (*)(const State& p, const Point& c, Args a);

    std::string_view id;
    std::string_view label;
    std::string_view help;
    Category category;
    std::span<const ParamDecl> params;
    // GLSL body. Folds/transforms/powers: statements over the state (3D: `inout vec4 p`; 2D:
    // `inout PlaneState s`) and `c`. Estimators: statements ending in `return <distance>;`.
    // Parameters are in scope by name.
    std::string_view glsl;
    ApplyFn apply = nullptr;        // non-estimators
    EstimateFn estimate = nullptr;  // estimators
    MembershipT membership{};       // the family's first kind unless the estimator says
    bool custom = false;            // a user's GLSL block (core/custom_block.hpp): no CPU body
    // A custom estimator whose GLSL is global-scope code defining `float DE(vec3)` (an imported
    // Fragmentarium DE): it computes the whole distance, so its formula has no other nodes.
    bool wholeDE = false;
    // A gradient twin names the estimator whose orbit value it differentiates (the same
    // parameters), so that the check measures the two side by side; it reads P4::orbitGradient,
    // for which the formula runs four more orbits per estimate.
    std::string_view gradientOf{};
    bool usesOrbitGradient() const { return !gradientOf.empty(); }
    // Whether the check offers this twin in place of the estimator it differentiates. A twin kept
    // for another program's convention (Mandelbulber2's halved delta DE) is measured only where a
    // formula chose it.
    bool offeredAsTwin = true;
    // The editor's "Add block" menu lists a block with a group in a submenu of that name under its
    // kind (the blocks that open Mandelbulber2's formulas), so that the kinds' own lists stay short.
    std::string_view menuGroup{};
    // Orbits evaluated per estimate (1, or 5 with the orbit gradient): the check weighs an
    // estimator's speed by it.
    int orbitsPerEstimate() const { return usesOrbitGradient() ? 5 : 1; }
    // A dIFS shape step (formulas/difs.hpp): it measures a shape and lowers P4::orbitDistance,
    // which only the `difs` estimator reads.
    bool difsShape = false;
    // 3D steps declare it; estimators, 2D blocks and custom blocks (unknown GLSL) bound nothing.
    DerivativeBound derivative = DerivativeBound::None;
    // Where the bound depends on the parameters (a power's map jumps at the atan2 cut unless the
    // power is an integer): the bound for these values, in place of `derivative`.
    DerivativeBound (*derivativeFor)(Args a) = nullptr;
    DerivativeBound derivativeAt(Args a) const { return derivativeFor ? derivativeFor(a) : derivative; }
    // Where and why the map jumps, in words, for a step that can (DerivativeBound::None, always or
    // for some values): `fraktal check` and the editor name it when it is what keeps a factor small.
    std::string_view jump{};
    // The step's stretch bound grows with |p| (twist and bend: the factor is about |rate| r): an
    // orbit let far out before it is stopped multiplies the running derivative by it at every
    // iteration, and the estimate shrinks towards nothing. The fit keeps such a stack's bailout low.
    bool stretchGrowsWithRadius = false;
    // The step's Degree: the index of the parameter that holds it (-1: the fixed value).
    int degreeParam = -1;
    double fixedDegree = 1.0;
    bool raisesDegree() const { return degreeParam >= 0 || fixedDegree != 1.0; }
    double degreeAt(Args a) const { return degreeParam >= 0 ? a.f(degreeParam) : fixedDegree; }

    bool isEstimator() const { return category == Category::Estimator; }
    int paramIndex(std::string_view name) const {
        for (size_t i = 0; i < params.size(); ++i)
            if (params[i].name == name) return int(i);
        return -1;
    }
};

using BlockDesc = BlockDescOf<P4, vec3, Membership>;
using ApplyFn = BlockDesc::ApplyFn;
using EstimateFn = BlockDesc::EstimateFn;

// What a block definition must provide; a block missing any of it fails to compile at its
// registration line in formulas/registry.cpp (2D: formulas/plane/registry.cpp).
template <class B>
concept BlockCommon = requires {
    { B::id } -> std::convertible_to<std::string_view>;
    { B::label } -> std::convertible_to<std::string_view>;
    { B::help } -> std::convertible_to<std::string_view>;
    { B::category } -> std::convertible_to<Category>;
    { B::glsl } -> std::convertible_to<std::string_view>;
    {std::span<const ParamDecl>(B::params)};
};

template <class B, class Desc>
concept StepBlockFor = BlockCommon<B> && requires(typename Desc::State& p, const typename Desc::Point& c, Args a) {
    { B::apply(p, c, a) } -> std::same_as<void>;
};

template <class B, class Desc>
concept EstimatorBlockFor = BlockCommon<B> &&
    requires(const typename Desc::State& p, const typename Desc::Point& c, Args a) {
    { B::estimate(p, c, a) } -> std::same_as<double>;
    { B::membership } -> std::convertible_to<typename Desc::MembershipKind>;
};

template <class B>
concept StepBlock = StepBlockFor<B, BlockDesc> && requires {
    { B::derivative } -> std::convertible_to<DerivativeBound>;
};
template <class B>
concept EstimatorBlock = EstimatorBlockFor<B, BlockDesc>;

// The index of B's parameter `name`; a name B does not declare fails to compile (a throw in a
// constant expression).
template <class B>
consteval int declaredParamIndex(std::string_view name) {
    for (size_t i = 0; i < B::params.size(); ++i)
        if (B::params[i].name == name) return int(i);
    throw "a block's Degree names a parameter it does not declare";
}

// Whether step B's map can jump: it declares so (DerivativeBound::None), or its bound depends on
// its values (a power that need not be a whole number).
template <class B>
consteval bool mayJump() {
    if constexpr (requires(Args a) { B::derivativeFor(a); }) return true;
    if constexpr (requires { B::derivative; }) return B::derivative == DerivativeBound::None;
    return false;
}

// The description of block B in family Desc.
template <class Desc, class B>
requires StepBlockFor<B, Desc> || EstimatorBlockFor<B, Desc>
constexpr Desc describeAs() {
    Desc d{.id = B::id,
           .label = B::label,
           .help = B::help,
           .category = B::category,
           .params = std::span<const ParamDecl>(B::params),
           .glsl = B::glsl};
    if constexpr (requires { B::menuGroup; }) d.menuGroup = B::menuGroup;
    if constexpr (EstimatorBlockFor<B, Desc>) {
        static_assert(B::category == Category::Estimator, "an estimator block must say so");
        d.estimate = &B::estimate;
        d.membership = B::membership;
        if constexpr (requires { B::gradientOf; }) d.gradientOf = B::gradientOf;
        if constexpr (requires { B::offeredAsTwin; }) d.offeredAsTwin = B::offeredAsTwin;
    } else {
        static_assert(B::category != Category::Estimator, "an estimator block needs estimate()");
        d.apply = &B::apply;
        if constexpr (requires { B::derivative; }) d.derivative = B::derivative;
        if constexpr (requires(Args a) { B::derivativeFor(a); }) d.derivativeFor = &B::derivativeFor;
        if constexpr (requires { B::stretchGrowsWithRadius; }) d.stretchGrowsWithRadius = B::stretchGrowsWithRadius;
        if constexpr (requires { B::difsShape; }) d.difsShape = B::difsShape;
        if constexpr (mayJump<B>()) {
            static_assert(
                requires { B::jump; }, "a step whose map can jump says where (static constexpr jump)");
            d.jump = B::jump;
        }
        if constexpr (requires { B::degree; }) {
            if constexpr (!B::degree.param.empty())
                d.degreeParam = declaredParamIndex<B>(B::degree.param);
            else
                d.fixedDegree = B::degree.fixed;
        }
    }
    return d;
}

template <class B>
requires StepBlock<B> || EstimatorBlock<B>
constexpr BlockDesc describe() { return describeAs<BlockDesc, B>(); }

// All registered blocks (formulas/registry.cpp).
std::span<const BlockDesc> allBlocks();
const BlockDesc* findBlock(std::string_view id);

}  // namespace fraktal
