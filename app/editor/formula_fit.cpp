#include "app/editor/formula_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "app/editor/camera_controller.hpp"
#include "app/editor/formula_edits.hpp"
#include "core/anim/animation.hpp"

namespace fraktal::editor {

namespace {

enum class Family { Power, EscapeLinear, Ifs, Unknown };

Family familyOf(const Formula& f) {
    bool power = false, addsPoint = false;
    for (const Node& n : f.nodes) {
        if (!n.enabled || !n.block) continue;
        if (n.block->custom) return Family::Unknown;
        if (n.block->category == Category::Power) power = true;
        if (n.block->id == "add_c") addsPoint = true;
    }
    if (power) return Family::Power;
    return addsPoint ? Family::EscapeLinear : Family::Ifs;
}

bool setEstimatorId(Formula& f, std::string_view id) {
    if (f.estimator.block && f.estimator.block->id == id) return false;
    const BlockDesc* b = findBlock(id);
    return b && setEstimator(f, *b);
}

// Direction i of n spread evenly over the unit sphere (golden-angle spiral).
vec3 fibonacciDirection(int i, int n) {
    const double y = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

}  // namespace

bool fitEstimatorToBlocks(Formula& f) {
    bool changed = false;
    auto atLeast = [&](double bailout) {
        if (f.bailout < bailout) f.bailout = bailout, changed = true;
    };
    switch (familyOf(f)) {
        case Family::Power:
            // The potential-corrected log estimate: the same near the object, tighter far from it,
            // so the measured step factor is larger (bench/README: DE evaluations per pixel). A
            // user's log estimate is kept.
            if (!f.estimator.block || f.estimator.block->id != "escape_log")
                changed |= setEstimatorId(f, "escape_potential");
            if (f.bailout > 16.0 || f.bailout < 1.5) f.bailout = 2.0, changed = true;
            break;
        case Family::EscapeLinear:
            changed |= setEstimatorId(f, "escape_linear");
            atLeast(100.0);
            break;
        case Family::Ifs:
            if (!f.estimator.block || f.estimator.block->membership != Membership::Distance)
                changed |= setEstimatorId(f, "box");
            atLeast(1000.0);
            break;
        case Family::Unknown: break;
    }
    return changed;
}

std::vector<vec3> probeSurface(const DistanceAt& de, double radius, int rays, int maxSteps) {
    std::vector<vec3> hits;
    const double epsilon = radius * 1e-4;
    for (int i = 0; i < rays; ++i) {
        const vec3 dir = fibonacciDirection(i, rays);
        // From the sphere straight through the origin and out the far side.
        double t = 0.0;
        for (int step = 0; step < maxSteps && t < 2.0 * radius; ++step) {
            const vec3 p = dir * (radius - t);
            const double d = de(p);
            if (!std::isfinite(d)) break;
            if (d < epsilon) {
                hits.push_back(p);
                break;
            }
            // Far outside, escape-time estimates overshoot (few iterations run): cap the step.
            t += std::min(d, radius / 16.0);
        }
    }
    return hits;
}

double fittedBoundRadius(const DistanceAt& de, double searchRadius, double fallback) {
    const std::vector<vec3> hits = probeSurface(de, searchRadius);
    if (hits.empty()) return fallback;
    double extent = 0.0;
    for (const vec3& h : hits) extent = std::max(extent, length(h));
    // Surface out at the search sphere: unbounded (e.g. a fold without its scale yet), no fit.
    if (extent > 0.9 * searchRadius) return fallback;
    // The probes see the outermost surface along their rays; between them it may reach further.
    return std::clamp(extent * 1.15, 0.05, 100.0);
}

Camera framedCamera(const Formula& f, const DistanceAt& de, const Camera& current) {
    const std::vector<vec3> hits = probeSurface(de, f.boundRadius);
    if (hits.empty()) return defaultViewFor(f, current);
    vec3 lo = hits.front(), hi = hits.front();
    for (const vec3& h : hits) lo = min(lo, h), hi = max(hi, h);
    const vec3 centre = (lo + hi) * 0.5;
    double radius = 0.0;
    for (const vec3& h : hits) radius = std::max(radius, length(h - centre));
    radius = std::max(radius, 1e-3);

    Camera cam = current;
    vec3 back = current.position - current.target;
    back = length(back) > 0.0 ? normalize(back) : normalize(vec3(0.6, 0.45, 0.8));
    const double halfFov = glm::radians(std::clamp(cam.fovY, 5.0, 120.0)) * 0.5;
    double distance = radius / std::sin(halfFov) * 1.05;
    cam.target = centre;
    cam.position = centre + back * distance;
    // Outside the surface, whatever the probes missed.
    for (int i = 0; i < 20 && !(de(cam.position) > radius * 1e-3); ++i) {
        distance *= 1.25;
        cam.position = centre + back * distance;
    }
    return cam;
}

bool fitFormulaAfterEdit(Formula& f, Camera& camera) {
    bool changed = fitEstimatorToBlocks(f);
    if (!f.cpuEvaluable()) return changed;
    const DistanceAt de = cpuDistance(f);
    const double bound = fittedBoundRadius(de, std::clamp(f.boundRadius * 2.0, 16.0, 100.0), f.boundRadius);
    if (bound != f.boundRadius) f.boundRadius = bound, changed = true;
    // Inside or against the new surface (a template's camera inside a larger object), or so far
    // from it that it is small in view (a camera framed for a larger object before the edit):
    // frame it. Small: from more than kSmallInView times the framed distance away (a Mandelbox-
    // like cube seen from 2.15 times the framed distance spans 38 % of the view's height).
    constexpr double kSmallInView = 2.0;
    const Camera framed = framedCamera(f, de, camera);
    const double away = length(camera.position - framed.target), fits = length(framed.position - framed.target);
    if (!(de(camera.position) > 0.01 * f.boundRadius) || away > kSmallInView * fits) camera = framed;
    return changed;
}

bool fitFormulaAfterEdit(Preset& p) {
    const BlockDesc* estimator = p.formula.estimator.block;
    const bool changed = fitFormulaAfterEdit(p.formula, p.camera);
    if (p.formula.estimator.block != estimator) dropEstimatorTracks(p.animation, p.formula.nodes.size());
    return changed;
}

}  // namespace fraktal::editor
