#include "core/scene/scene_import.hpp"

#include <algorithm>
#include <cmath>

#include "core/import/fract_import.hpp"
#include "core/import/frag_import.hpp"
#include "core/mesh/brick_sampler.hpp"
#include "core/safe_step.hpp"
#include "core/scene/distance.hpp"
#include "core/scene/formula_fit.hpp"

namespace fraktal {

bool isImportedSceneFile(const std::filesystem::path& path) { return mb2::isFractPath(path) || frag::isFragPath(path); }

std::string importedSceneProgram(const std::filesystem::path& path) {
    return mb2::isFractPath(path) ? "Mandelbulber2" : frag::isFragPath(path) ? "Fragmentarium" : "";
}

namespace {

// The bound sphere about the origin: fitted to the object found inside the view range; an object
// that reaches out to it (a tiling such as the pseudo-Kleinian) keeps a bound that holds the
// camera and everything Mandelbulber2 would march to (view_distance_max from the camera).
void fitBound(Preset& p) {
    const double viewRange = p.formula.boundRadius;  // view_distance_max, as imported
    const double reach = std::min(length(p.camera.position) + viewRange, 1e4);
    const double search = std::clamp(std::max(viewRange, 2.0 * length(p.camera.target)), 4.0, 1e4);
    p.formula.boundRadius = fittedBoundRadius(cpuDistance(p.formula), search, reach);
}

// What fraktal cannot express refuses the file unless lenient, each thing named.
void refuseUnlessLenient(const std::filesystem::path& path, const ImportedScene& scene,
                         const SceneImportOptions& options) {
    if (scene.unsupported.empty() || options.lenient) return;
    std::string list;
    for (const std::string& item : scene.unsupported) list += "\n  " + item;
    throw PresetError(path.string(), "",
                      "uses what fraktal cannot express, so nothing was written (--lenient writes the preset "
                      "without it and lists it in the description):" +
                          list);
}

// A ray keeps the reach of 256 full steps at the least step factor: a file's low factor that no
// measurement replaced (an object drawn by its estimate alone, nothing inside it to measure
// against: a Menger sponge at 250 iterations; a frag's FudgeFactor) would otherwise end rays
// before the surface.
void keepReachOf256Steps(Preset& p) {
    double leastFactor = p.formula.deFactor;
    for (const CombinedFractal& c : p.formula.fractals) leastFactor = std::min(leastFactor, c.formula.deFactor);
    p.render.maxSteps = std::max(p.render.maxSteps, std::min(int(std::ceil(256.0 / leastFactor)), 4096));
}

// What the import built must be a preset fraktal reads back: a value the mapping let through
// outside a range is an error here, naming the file, not a preset that fails to load later.
Preset readBack(const std::filesystem::path& path, const Preset& preset) {
    try {
        return parsePreset(serializePreset(preset), path.string());
    } catch (const PresetError& e) {
        throw PresetError(path.string(), e.field(), "the imported scene is not a valid preset: " + e.reason());
    }
}

// The bound sphere of an object whose estimate only a sampler evaluates (a frag's, on the GL
// probe): the mesher's brick pruning (mesh::planBricks, batched) over the cube of `searchRadius`
// at 256^3 finds the bricks where the estimate leaves room for surface; the sphere through their
// farthest corners holds the object. The cube shrinks to that sphere until it stops shrinking
// (each round's bricks are finer). `fallback` when no brick may hold surface, or when the first
// cube's faces do (the object reaches out to the search cube: a tiling).
double fittedBoundOnSampler(FormulaSampler& sampler, double searchRadius, double fallback) {
    constexpr int kVoxels = 256;
    double radius = searchRadius;
    for (int round = 0; round < 4; ++round) {
        const mesh::Box cube{vec3(-radius), vec3(radius)};
        const mesh::GridLayout layout = mesh::layoutOfBox(cube, kVoxels);
        const mesh::BrickPlan plan = mesh::planBricks(sampler, layout, 1e18, 0);
        if (plan.bricks.empty()) return round == 0 ? fallback : radius;
        const int last = layout.bricksAcross() - 1;
        const double brick = mesh::kBrickSize * layout.voxel;
        double extent = 0.0;
        for (const auto& b : plan.bricks) {
            if (round == 0 && (std::min({b[0], b[1], b[2]}) == 0 || std::max({b[0], b[1], b[2]}) == last))
                return fallback;
            vec3 farthest;
            for (int a = 0; a < 3; ++a) {
                const double lo = layout.minCorner[a] + b[size_t(a)] * brick;
                farthest[a] = std::max(std::abs(lo), std::abs(lo + brick));
            }
            extent = std::max(extent, length(farthest));
        }
        if (extent > 0.9 * radius) return std::max(extent, 0.05);
        radius = extent;
    }
    return std::max(radius, 0.05);
}

// A Fragmentarium frag's safe step, measured where the caller gives a GL sampler (its DE has no CPU
// twin). FragM multiplies the estimate by FudgeFactor; the measured factor takes its place. A frag
// whose estimate nothing vouches for (no ray meets the object, or no factor is safe) keeps its
// FudgeFactor, and the description says so.
void measureFragFactor(frag::FragImport& result, ImportedScene& scene, const SceneImportOptions& options) {
    if (!options.measure || !options.glslSampler) return;
    Formula& f = result.preset.formula;
    const std::unique_ptr<FormulaSampler> sampler = options.glslSampler(f);
    if (!sampler) return;
    EstimatorMeasurement m = measureSafeStep(*sampler, result.preset.camera);
    if (m.report.samples == 0 || !hasSafeStepFactor(m)) {
        const frag::ImportItem kept{"FudgeFactor", m.report.samples == 0
                                                       ? "kept as the step factor: no ray of the check met the object"
                                                       : "kept as the step factor: the estimate overshoots by more "
                                                         "than any factor makes up for"};
        result.approximated.push_back(kept);
        scene.approximated.push_back(kept.text());
        return;
    }
    f.deFactor = m.factor;
    f.deFactorMeasuredFor = stepFactorTag(f);
    // With an estimate now safe to step by, the bound is fitted to the object (the import framed
    // the camera's view instead), and the step measured again in it: its rays sample the object
    // closer, where an estimate may overshoot more. A bound whose measurement fails is not taken.
    const double framing = f.boundRadius;
    const double firstFactor = f.deFactor;
    f.boundRadius = fittedBoundOnSampler(*sampler, framing, framing);
    if (f.boundRadius == framing) return;
    m = measureSafeStep(*sampler, result.preset.camera);
    if (m.report.samples == 0 || !hasSafeStepFactor(m)) {
        f.boundRadius = framing;
        f.deFactor = firstFactor;
        return;
    }
    f.deFactor = m.factor;
    // And against the baseline marcher's true distances, as `fraktal check` tests a preset (its
    // 120 rays are the first of these 200): the safe-step rounds follow the camera's rays, and an
    // estimate bent by the DE's own transforms (a rotation inside the iteration) can overshoot
    // more on rays from the bound's sphere.
    const ConservativenessReport c = checkConservativeness(*sampler, result.preset.camera);
    if (c.samples > 0 && !c.conservative()) f.deFactor *= c.safeStepMultiplier();
}

// The factor measured as above, and the hit threshold after it: FragM's hit test, DE * FudgeFactor
// < 10^Detail * t, and fraktal's, DE * deFactor < threshold, both apply to the scaled estimate, so
// the threshold follows the factor and the surface stays where FragM draws it (a sphere whose
// rippled estimate measured 0.10 under FudgeFactor 1 was drawn ten thresholds too fat:
// tests/data/frag_import/annotations.frag), as for Mandelbulber2's DE_factor below.
void measureFragStep(frag::FragImport& result, ImportedScene& scene, const SceneImportOptions& options) {
    const double fudge = result.preset.formula.deFactor;
    measureFragFactor(result, scene, options);
    RenderSettings& r = result.preset.render;
    r.detail = std::clamp(r.detail * result.preset.formula.deFactor / fudge, 1e-3, 100.0);
}

// A Fragmentarium frag: its DE as a whole-DE estimator, its step factor measured on the GPU when
// the caller can (measureFragStep).
ImportedScene importFragScene(const std::filesystem::path& path, const SceneImportOptions& options) {
    const frag::FragFile file = frag::loadFragFile(path, frag::importParseOptions(options.includeDirs));
    if (file.doNotRun)
        throw PresetError(path.string(), "", "is an include-only frag (#donotrun): open the frag that includes it");
    frag::FragImport result = frag::importFrag(file, {.presetName = options.fragPreset});
    ImportedScene scene;
    for (const frag::ImportItem& item : result.unsupported) scene.unsupported.push_back(item.text());
    for (const frag::ImportItem& item : result.approximated) scene.approximated.push_back(item.text());
    for (const frag::FragPreset& p : file.presets)
        if (!p.keyFrame() &&
            std::find(scene.presetChoices.begin(), scene.presetChoices.end(), p.name) == scene.presetChoices.end())
            scene.presetChoices.push_back(p.name);
    scene.presetUsed = result.presetUsed;
    refuseUnlessLenient(path, scene, options);
    result.preset.name = path.stem().string();
    measureFragStep(result, scene, options);
    // The raytracer's floor joins the measured DE; the bound reaches as far from the eye as FragM
    // marches to it (within what a preset holds), since fraktal draws nothing outside the bound.
    if (!result.objects.empty()) {
        Formula& f = result.preset.formula;
        f.objects = result.objects;
        f.boundRadius =
            std::max(f.boundRadius, std::min(length(result.preset.camera.position) + result.objectReach, 1e3));
    }
    frag::holdShadingLengths(result);
    result.preset.description = frag::importDescription(file, result);
    keepReachOf256Steps(result.preset);
    scene.preset = readBack(path, result.preset);
    return scene;
}

}  // namespace

ImportedScene importSceneFile(const std::filesystem::path& path, const SceneImportOptions& options) {
    if (frag::isFragPath(path)) return importFragScene(path, options);
    const mb2::FractFile file = mb2::loadFractFile(path);
    mb2::FractImport result = mb2::importFract(file);
    ImportedScene scene;
    for (const mb2::ImportItem& item : result.unsupported) scene.unsupported.push_back(item.text());
    for (const mb2::ImportItem& item : result.approximated) scene.approximated.push_back(item.text());
    refuseUnlessLenient(path, scene, options);
    result.preset.name = path.stem().string();
    result.preset.description = mb2::importDescription(file, result);
    if (result.preset.formula.cpuEvaluable() && !result.preset.formula.nodes.empty()) fitBound(result.preset);
    // Each fractal of a boolean combination is measured alone, in its placement: its factor scales
    // its own estimate (a union, intersection or difference of safe estimates is safe).
    for (size_t i = 0; options.measure && result.preset.formula.cpuEvaluable() &&
                       !result.preset.formula.nodes.empty() && i <= result.preset.formula.fractals.size();
         ++i) {
        const EstimatorMeasurement m = measureSafeStep(result.preset.formula.fractalAlone(i), result.preset.camera);
        if (i > 0) {
            result.preset.formula.fractals[i - 1].formula.deFactor = m.factor;
            continue;
        }
        if (hasSafeStepFactor(m))
            // The measured factor replaces the file's DE_factor: Mandelbulber2's artists lower that
            // for its own estimate (0.05 in its fog examples), and at a twentieth of the safe step
            // a ray runs out of steps before it meets the surface.
            // The hit threshold applies to the scaled estimate (fract_import.cpp): it follows,
            // also where nothing was measured and the factor becomes 1 (formula/img
            // amazing_surf_mod2 at DE_factor 0.18 had kept its threshold, a fifth of
            // Mandelbulber2's, and drew holes through its sheet).
            result.preset.render.detail =
                std::clamp(result.preset.render.detail * m.factor / result.preset.formula.deFactor, 1e-3, 100.0);
        result.preset.formula.deFactor = m.factor;
        if (m.report.samples > 0) result.preset.formula.deFactorMeasuredFor = stepFactorTag(result.preset.formula);
    }
    keepReachOf256Steps(result.preset);
    scene.preset = readBack(path, result.preset);
    return scene;
}

Preset loadSceneFile(const std::filesystem::path& path,
                     const std::function<std::unique_ptr<FormulaSampler>(const Formula&)>& glslSampler) {
    if (isImportedSceneFile(path)) return importSceneFile(path, {.glslSampler = glslSampler}).preset;
    return loadPreset(path);
}

}  // namespace fraktal
