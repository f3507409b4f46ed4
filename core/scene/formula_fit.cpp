#include "core/scene/formula_fit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "core/animation.hpp"
#include "core/de_check.hpp"
#include "core/random_vec.hpp"

namespace fraktal {

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

// The estimator `id` with its defaults, unless it closes the stack already (its values kept).
bool setEstimatorId(Formula& f, std::string_view id) {
    if (f.estimator.block && f.estimator.block->id == id) return false;
    const BlockDesc* b = findBlock(id);
    if (!b || !b->isEstimator()) return false;
    f.estimator = Node::make(*b);
    return true;
}

// Direction i of n spread evenly over the unit sphere (golden-angle spiral).
vec3 fibonacciDirection(int i, int n) {
    const double y = 1.0 - 2.0 * (i + 0.5) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - y * y));
    const double phi = i * std::numbers::pi * (3.0 - std::sqrt(5.0));
    return {r * std::cos(phi), y, r * std::sin(phi)};
}

bool stretchGrowsWithRadius(const Formula& f) {
    for (const Node& n : f.nodes)
        if (n.enabled && n.block->stretchGrowsWithRadius) return true;
    return false;
}

// Points inside `f`'s object where rays across its bound first meet it: `rays` rays from random
// points on the bound sphere towards random points within half its radius (seeded), marched by
// membership in steps of 1/2000 of the diameter (the baseline marcher, core/de_check.hpp).
std::vector<vec3> firstPointsInside(const Formula& f, int rays) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    auto inBall = [&] {
        vec3 v;
        do v = randomVec3(u, rng);
        while (dot(v, v) > 1.0 || dot(v, v) < 1e-6);
        return v;
    };
    std::vector<vec3> out;
    for (int i = 0; i < rays; ++i) {
        const vec3 origin = normalize(inBall()) * f.boundRadius;
        const vec3 dir = normalize(inBall() * (0.5 * f.boundRadius) - origin);
        double t0, t1;
        if (!clipToBound(f, origin, dir, t0, t1)) continue;
        if (const BaselineHit hit = baselineMarch(f, origin, dir, t0, t1, f.boundRadius / 1000.0); hit.hit)
            out.push_back(origin + dir * hit.t);
    }
    return out;
}

// The smallest bailout among 2, 4, 8, ... up to `reference` at which membership agrees with the
// reference bailout's at all but 1 in 500 of 2000 points spread through the bound (seeded): an
// IFS estimate whose orbit is stopped sooner sees the same object, and a step whose stretch
// grows with |p| has multiplied the running derivative less by then. An object that fills under
// 1 % of the bound is missed by those points, so that a bailout at which it vanishes agrees with
// them (a twisted octahedral KIFS, twist rate -3.25, at bailout 2: no ray of `fraktal check` met
// it, where at 4 and above the same 6 of 120 did); there, the first points inside along 64 rays
// across the bound must also stay inside at all but 1 in 10 of them.
double smallestBailoutKeepingTheObject(const Formula& f, double reference) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    std::vector<vec3> points;
    while (points.size() < 2000) {
        const vec3 p = randomVec3(u, rng);
        if (length(p) <= 1.0) points.push_back(p * f.boundRadius);
    }
    Formula g = f;
    g.bailout = reference;
    std::vector<bool> inside;
    size_t insideCount = 0;
    for (const vec3& p : points) {
        inside.push_back(evaluate(g, p).inside);
        insideCount += inside.back();
    }
    const std::vector<vec3> surface =
        insideCount < points.size() / 100 ? firstPointsInside(g, 64) : std::vector<vec3>{};
    for (double bailout = 2.0; bailout < reference; bailout *= 2.0) {
        g.bailout = bailout;
        size_t differ = 0;
        for (size_t i = 0; i < points.size() && differ <= points.size() / 500; ++i)
            differ += evaluate(g, points[i]).inside != inside[i];
        if (differ > points.size() / 500) continue;
        size_t lost = 0;
        for (size_t i = 0; i < surface.size() && lost <= surface.size() / 10; ++i)
            lost += !evaluate(g, surface[i]).inside;
        if (lost <= surface.size() / 10) return bailout;
    }
    return reference;
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
            // The linear estimate sees the limit set, and the iterations leave a shell around it
            // that thickens with the bailout: at 20 the Amazing Surf's estimate overshoots the
            // shell's face 1.08x at factor 1 where at 100 it did 1.81x (`fraktal check`), and a
            // Mandelbox marches about as fast at 20 as at 100 (factor x median 0.239 and 0.227).
            atLeast(20.0);
            break;
        case Family::Ifs:
            if (!f.estimator.block || f.estimator.block->membership != Membership::Distance)
                changed |= setEstimatorId(f, "box");
            if (stretchGrowsWithRadius(f)) {
                // A twisted octahedral KIFS (twist rate 0.5, 12 iterations) at bailout 1000 has an
                // estimate of 1e-13 to 2e-4 over its bound (`fraktal check`: speed 0.0000); at 4 it
                // is the same object with speed 0.287.
                const double bailout = smallestBailoutKeepingTheObject(f, 1000.0);
                if (bailout != f.bailout) f.bailout = bailout, changed = true;
            } else {
                atLeast(1000.0);
            }
            break;
        case Family::Unknown: break;
    }
    return changed;
}

std::vector<vec3> probeSurface(const DistanceAt& de, double radius, int rays, int maxSteps) {
    std::vector<vec3> hits;
    cpu::MarchRule rule;
    rule.epsilon = radius * 1e-4;
    // Far outside, escape-time estimates overshoot (few iterations run): cap the step.
    rule.maxStep = radius / 16.0;
    for (int i = 0; i < rays; ++i) {
        // From the sphere straight through the origin and out the far side.
        const vec3 dir = fibonacciDirection(i, rays);
        const vec3 ro = dir * radius;
        if (const std::optional<double> t = traceDistance(de, ro, -dir, 0.0, 2.0 * radius, rule, maxSteps))
            hits.push_back(ro - dir * *t);
    }
    return hits;
}

namespace {

// A surface point near p: p moved down the DE's gradient (central differences) by the DE until
// the DE is under epsilon, at most 32 moves; none where the DE is not finite or does not get there.
std::optional<vec3> surfaceNear(const DistanceAt& de, vec3 p, double epsilon) {
    for (int move = 0; move < 32; ++move) {
        const double d = de(p);
        if (!std::isfinite(d)) return std::nullopt;
        if (d < epsilon) return p;
        const double h = std::max(0.05 * d, epsilon);
        const vec3 gradient(de(p + vec3(h, 0, 0)) - de(p - vec3(h, 0, 0)),
                            de(p + vec3(0, h, 0)) - de(p - vec3(0, h, 0)),
                            de(p + vec3(0, 0, h)) - de(p - vec3(0, 0, h)));
        if (!(length(gradient) > 0.0)) return std::nullopt;
        p -= normalize(gradient) * d;
    }
    return std::nullopt;
}

}  // namespace

double fittedBoundRadius(const DistanceAt& de, double searchRadius, double fallback) {
    const std::vector<vec3> hits = probeSurface(de, searchRadius);
    if (hits.empty()) return fallback;
    double extent = 0.0;
    for (const vec3& h : hits) extent = std::max(extent, length(h));
    // The probes pass through the origin, so they meet a flat object (a sheet) at its rim only
    // where they lie in its plane: the Amazing Surf's were seen out to 6.1 where its sheet
    // reaches 8.4. Cells of a grid over a sphere whose DE leaves room for surface inside them
    // (under the half-diagonal) and that reach beyond the extent found so far are followed down
    // the DE to the surface there.
    auto followGrid = [&](double gridRadius) {
        const int cells = 24;
        const double cell = 2.0 * gridRadius / cells, halfDiagonal = cell * std::sqrt(3.0) / 2.0;
        const double epsilon = gridRadius * 1e-4;
        for (int i = 0; i < cells; ++i)
            for (int j = 0; j < cells; ++j)
                for (int k = 0; k < cells; ++k) {
                    const vec3 centre = (vec3(i, j, k) + 0.5) * cell - gridRadius;
                    const double r = length(centre);
                    if (r > gridRadius || r + halfDiagonal <= extent || !(de(centre) < halfDiagonal)) continue;
                    if (const std::optional<vec3> s = surfaceNear(de, centre, epsilon);
                        s && length(*s - centre) < 2.0 * cell)
                        extent = std::max(extent, length(*s));
                }
    };
    followGrid(searchRadius);
    // Over a search sphere many times the object (an imported view range of 50 about a bulb of
    // radius 2) the cells are wider than the object's hairs and their DE's surface too fine for
    // a follow from a cell's centre: the power-2 bulb of Mandelbulber2's toolbar was seen out to
    // 1.56 where it reaches 1.96. A second grid over twice the extent found looks again there.
    if (2.0 * extent < 0.5 * searchRadius) followGrid(2.0 * extent);
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
    // The object's extent, not the march: probes at the formula's step factor (0.001 after a
    // structure without a safe one) would crawl and find no surface.
    Formula shape = f;
    shape.deFactor = 1.0;
    const DistanceAt de = cpuDistance(shape);
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

Camera defaultViewFor(const Formula& f, const Camera& current) {
    Camera cam = current;
    cam.target = vec3(0.0);
    cam.up = vec3(0.0, 1.0, 0.0);
    const double halfFov = glm::radians(std::clamp(cam.fovY, 5.0, 120.0)) * 0.5;
    const double distance = f.boundRadius / std::sin(halfFov) * 0.9;
    cam.position = normalize(vec3(0.6, 0.45, 0.8)) * distance;
    return cam;
}

}  // namespace fraktal
