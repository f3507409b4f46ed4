#pragma once
#include "core/block.hpp"

namespace fraktal::blocks {

// A scale that varies with the iteration (Mandelbulber2's "scale vary", DarkBeam's: aux.actualScaleA
// in fractal_formulas.cpp, e.g. BoxFoldBulbPow2V2Iteration). The orbit carries an offset a
// (P4::varyScale; GLSL: varyScale), 0 when it starts. Each step scales by a + scale, then, when it
// updates, moves a by vary (|a| - limit), so that the scale drifts from `scale` towards
// scale + limit (for 0 < vary < 1) over the iterations. With `reset` a becomes -vary (|a| - limit)
// instead (Mandelbulber2's option M). The offset does not depend on the point: at one iteration
// every point is scaled alike, so the running scale gains |a + scale| (a Global factor, as the
// plain scale's). The scaling is about `center` (Mandelbulber2's dIFS formulas take their
// "reverse offsets" off before the scale and put them back after).
// With `from_scale` the offset follows Mandelbulber2's other varying scale, aux.actualScale
// (AboxMod11Iteration of 2.20: actualScale = scale + vary (|actualScale| - 1) at the start of each
// iteration, from the Mandelbox scale): when the step updates, a first becomes
// vary (|a + scale| - limit), and then the step scales by a + scale. With a starting at 0 the whole
// scale starts at `scale`, as actualScale starts at the formula's scale.
struct ScaleVary {
    static constexpr std::string_view id = "scale_vary";
    static constexpr std::string_view menuGroup = "Mandelbulber2";
    static constexpr std::string_view label = "Scale, varying";
    static constexpr std::string_view help =
        "Scale by a factor that drifts with the iteration: by a + scale, then a moves by vary (|a| - limit); a "
        "starts at 0 for each orbit and is shared by all such steps.";
    static constexpr Category category = Category::Transform;
    static constexpr DerivativeBound derivative = DerivativeBound::Global;
    static constexpr std::array params{
        ParamDecl{"scale", ParamType::Float, {2.0, 0.0, 0.0}, -4.0, 4.0, "The scale while the offset a is 0."},
        ParamDecl{"vary", ParamType::Float, {0.1, 0.0, 0.0}, -2.0, 2.0, "How far a moves each update."},
        ParamDecl{"limit", ParamType::Float, {1.0, 0.0, 0.0}, -4.0, 4.0, "The |a| at which a stops moving."},
        toggleParam("update", true, "On: this step moves a after scaling; off: it only reads it."),
        toggleParam("reset", false, "On: a becomes -vary (|a| - limit) rather than moving by it."),
        ParamDecl{"center", ParamType::Vec3, {0.0, 0.0, 0.0}, -10.0, 10.0, "Fixed point of the scaling."},
        toggleParam("from_scale", false,
                    "On: before scaling, a becomes vary (|a + scale| - limit) (Mandelbulber2's actualScale) rather "
                    "than moving after it."),
    };

    static constexpr std::string_view glsl = R"(
    if (from_scale > 0.5 && update > 0.5) varyScale = vary * (abs(varyScale + scale) - limit);
    float s = varyScale + scale;
    p.xyz = (p.xyz - center) * s + center;
    p.w *= abs(s);
    if (from_scale < 0.5 && update > 0.5) {
        float change = vary * (abs(varyScale) - limit);
        varyScale = reset > 0.5 ? -change : varyScale - change;
    }
)";
    static void apply(P4& p, const vec3&, Args a) {
        const double scale = a.f(0), vary = a.f(1), limit = a.f(2), update = a.f(3), reset = a.f(4);
        const vec3 center = a.v3(5);
        const bool fromScale = a.f(6) > 0.5;
        if (fromScale && update > 0.5) p.varyScale = vary * (abs(p.varyScale + scale) - limit);
        double s = p.varyScale + scale;
        p.xyz = (p.xyz - center) * s + center;
        p.w *= abs(s);
        if (!fromScale && update > 0.5) {
            double change = vary * (abs(p.varyScale) - limit);
            p.varyScale = reset > 0.5 ? -change : p.varyScale - change;
        }
    }
};

}  // namespace fraktal::blocks
