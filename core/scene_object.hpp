// Objects beside the fractal: simple shapes joined with the fractal's estimate, cut from it or
// intersecting it, in order, after the estimator (Mandelbulber2's primitives and its limit box).
// Each kind declares its parameters once and its distance in GLSL and C++ side by side
// (formulas/objects.hpp); the distance is measured in the object's own frame, placed by a centre
// and a turn.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "core/block.hpp"

namespace fraktal {

// How an object meets what comes before it: the union (joined), the intersection (the fractal
// kept inside the object: a limit box) or the difference (the object carved out of it).
enum class ObjectOperation { Join, Intersect, Carve };
inline constexpr std::string_view kObjectOperationNames[] = {"join", "intersect", "carve"};

// One kind of object: its parameters and its signed distance at a point of its own frame.
// GLSL: statements over `vec3 pos` (the point in the object's frame) ending in
// `return <distance>;`, the parameters in scope by name.
struct ObjectDesc {
    std::string_view id;
    std::string_view label;
    std::string_view help;
    std::span<const ParamDecl> params;
    std::string_view glsl;
    double (*distance)(const vec3& pos, Args a) = nullptr;
};

template <class O>
concept ObjectKind = requires(const vec3& pos, Args a) {
    { O::id } -> std::convertible_to<std::string_view>;
    { O::label } -> std::convertible_to<std::string_view>;
    { O::help } -> std::convertible_to<std::string_view>;
    { O::glsl } -> std::convertible_to<std::string_view>;
    {std::span<const ParamDecl>(O::params)};
    { O::distance(pos, a) } -> std::same_as<double>;
};

template <ObjectKind O>
constexpr ObjectDesc describeObject() {
    return ObjectDesc{O::id, O::label, O::help, std::span<const ParamDecl>(O::params), O::glsl, &O::distance};
}

// All registered kinds (formulas/registry.cpp).
std::span<const ObjectDesc> allObjects();
const ObjectDesc* findObject(std::string_view id);

// At most this many objects per formula (each is a function and a few uniforms).
inline constexpr int kMaxObjects = 8;

// A neutral light grey: a surface that takes the light's colour, as a studio's grey card does.
inline constexpr double kDefaultObjectColor = 0.7;

// Which surface a point is nearest to, as the objects' combine reports it: the fractal (and any
// combined with it, coloured by the palette) or object k of Formula::objects.
inline constexpr int kFractalSurface = -1;

// The cell a repeated point falls in, centred on the origin: per axis with period > 0, x - period
// * floor(x / period + 1/2) (Mandelbulber2's CVector3::mod); an axis of period 0 is kept.
vec3 repeatCell(const vec3& x, const vec3& period);

// Where a shape sits: its own frame turned by `angle` degrees about `axis` and moved to `center`.
// Objects beside the fractal and combined fractals (core/formula.hpp) are placed by one.
struct Placement {
    vec3 center{0.0};
    vec3 axis{0.0, 0.0, 1.0};
    double angle = 0.0;

    // The rotation taking world directions into the frame (the inverse of its turn).
    glm::dmat3 localFromWorld() const;
    bool turned() const { return angle != 0.0 && length(axis) >= 1e-12; }
};

struct SceneObject : Placement {
    const ObjectDesc* block = nullptr;  // the kind (named `block` so the node readers serve it)
    std::vector<ParamValue> values;     // one per block->params, in declaration order
    ObjectOperation operation = ObjectOperation::Join;
    bool hollow = false;  // |distance|: only the shell (Mandelbulber2's "empty")
    bool enabled = true;
    // Repeated in cells this wide about the origin of its own frame, per axis (0: once), as
    // Mandelbulber2 repeats its primitives (primitives.cpp: after the turn).
    vec3 repeat{0.0};
    // The object's own reflectance, in [0, 1]: the fractal's orbit-trap palette says nothing
    // about a floor or a ball. Linear Rec.709 like the scene's other colours (lights, fog,
    // background), taken into the working space with them where the scene is resolved
    // (resolveShading; the editor's viewport: CoreViewportView::workingFormula), not
    // display-referred like the palette's a and b (raised to 2.2 in shade.glsl): a reflectance
    // multiplies the light, and the colour widget then takes the same numbers as the light's and
    // the fog's beside it, so a scene keeps its look in either working space.
    vec3 color{kDefaultObjectColor};

    static SceneObject make(const ObjectDesc& kind);  // with default parameter values
    Args args() const { return Args{values.data()}; }
    double distanceAt(const vec3& pos) const;  // in world units, hollow applied
};

// The fractal's distance and membership combined with each enabled object in order. Membership:
// escape-time estimators keep `inside` as the flag of the orbit's boundedness, which each object
// then sets or clears; distance estimators are inside where the combined distance is <= 0.
// `surface` becomes the index of the object whose distance the result is (the nearest one joined,
// the one an intersection or a carve takes), and is left as it was where the fractal's is.
double combineObjects(const std::vector<SceneObject>& objects, const vec3& pos, double distance, bool& inside,
                      bool escapeTime, int& surface);

}  // namespace fraktal
