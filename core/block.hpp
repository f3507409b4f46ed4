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

enum class ParamType { Float, Vec3 };

// One parameter. Floats keep their value in x. The range is what the editor's widget offers and
// what a preset may hold (per component for vectors).
struct ParamDecl {
    std::string_view name;
    ParamType type = ParamType::Float;
    vec3 defaultValue{0.0};
    double min = 0.0;
    double max = 1.0;
    std::string_view help;
    bool direction = false;  // a vector used as a direction: must not be zero
};

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

using ApplyFn = void (*)(P4& p, const vec3& c, Args a);
using EstimateFn = double (*)(const P4& p, const vec3& c, Args a);

// The type-erased description that the rest of the program sees.
struct BlockDesc {
    std::string_view id;
    std::string_view label;
    std::string_view help;
    Category category;
    std::span<const ParamDecl> params;
    // GLSL body. Folds/transforms/powers: statements over `inout vec4 p` and `vec3 c`.
    // Estimators: statements ending in `return <distance>;`. Parameters are in scope by name.
    std::string_view glsl;
    ApplyFn apply = nullptr;        // non-estimators
    EstimateFn estimate = nullptr;  // estimators
    Membership membership = Membership::Distance;
    bool custom = false;  // a user's GLSL block (core/custom_block.hpp): no CPU body

    bool isEstimator() const { return category == Category::Estimator; }
    int paramIndex(std::string_view name) const;
};

// What a block definition must provide; a block missing any of it fails to compile at its
// registration line in formulas/registry.cpp.
template <class B>
concept BlockCommon = requires {
    { B::id } -> std::convertible_to<std::string_view>;
    { B::label } -> std::convertible_to<std::string_view>;
    { B::help } -> std::convertible_to<std::string_view>;
    { B::category } -> std::convertible_to<Category>;
    { B::glsl } -> std::convertible_to<std::string_view>;
    { std::span<const ParamDecl>(B::params) };
};

template <class B>
concept StepBlock = BlockCommon<B> && requires(P4& p, const vec3& c, Args a) {
    { B::apply(p, c, a) } -> std::same_as<void>;
};

template <class B>
concept EstimatorBlock = BlockCommon<B> && requires(const P4& p, const vec3& c, Args a) {
    { B::estimate(p, c, a) } -> std::same_as<double>;
    { B::membership } -> std::convertible_to<Membership>;
};

template <class B>
    requires StepBlock<B> || EstimatorBlock<B>
constexpr BlockDesc describe() {
    BlockDesc d{B::id, B::label, B::help, B::category, std::span<const ParamDecl>(B::params), B::glsl};
    if constexpr (EstimatorBlock<B>) {
        static_assert(B::category == Category::Estimator, "an estimator block must say so");
        d.estimate = &B::estimate;
        d.membership = B::membership;
    } else {
        static_assert(B::category != Category::Estimator, "an estimator block needs estimate()");
        d.apply = &B::apply;
    }
    return d;
}

// All registered blocks (formulas/registry.cpp).
std::span<const BlockDesc> allBlocks();
const BlockDesc* findBlock(std::string_view id);

}  // namespace fraktal
