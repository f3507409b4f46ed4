// `fraktal check PRESET`: load a preset, print its formula, compile its GLSL, evaluate the DE on
// a grid and against the seed's baseline marcher, and say whether marching it is safe.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <random>

#include "cli/commands.hpp"
#include "core/atomic_file.hpp"
#include "core/de_check.hpp"
#include "core/gl/context.hpp"
#include "core/gl/de_probe.hpp"
#include "core/import/frag_file.hpp"
#include "core/json_reader.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/plane/plane_renderer.hpp"
#include "core/preset.hpp"
#include "core/preset_text_edit.hpp"
#include "core/random_vec.hpp"
#include "core/safe_step.hpp"
#include "core/scene/formula_fit.hpp"
#include "core/scene/scene_import.hpp"
#include "core/scene/slow_stack.hpp"

namespace fraktal::cli {

namespace {

struct CheckOptions {
    std::string preset;
    int grid = 24;
    int rays = 120;
    int steps = ConservativenessOptions{}.stepsAcrossBound;
    uint64_t seed = 1;
    // Check the preset as its animation has it at this frame (keyed parameters, camera, step
    // factor): a parameter animation may take a stack out of the step factor that suits frame 0.
    std::optional<int> frame;
    // Write the measured safe step factor into the preset (formula.deFactor, the rest of the
    // file as it is, atomically).
    bool apply = false;
    // Fit the estimator, the bailout and the bound to the blocks first, as the editor does after
    // a structure change, then take the estimator the check measures fastest for them; with
    // --apply those are written too.
    bool fit = false;
};

// The stack as the editor closes it after a structure change: the estimator and bailout fitted to
// the blocks, the bound to the object (fitFormulaAfterEdit; the camera stays the file's), then the
// estimator the check measures fastest among those that share its membership, at its factor.
// A candidate under which none of the check's rays meets the object (nothing to measure), or
// whose estimate no step factor makes safe, is rejected: the fitted estimator and bailout within
// the fitted bound, then within the file's bound; when neither is kept, the file's estimator,
// bailout and bound stay, and the check measures them. Prints what changed, or why nothing did.
// Returns whether the fit was taken.
bool fitToBlocks(Preset& preset, const SafeStepOptions& options) {
    Formula& f = preset.formula;
    if (!f.cpuEvaluable()) {
        std::printf("fit: not fitted (custom GLSL blocks: the fit measures on the CPU)\n");
        return false;
    }
    const Formula before = f;
    Formula fitted = f;
    Camera framed = preset.camera;
    fitFormulaAfterEdit(fitted, framed);
    // Three significant digits, rounded up: the file gets a number a person reads.
    const double digits = std::pow(10.0, std::floor(std::log10(fitted.boundRadius)) - 2.0);
    fitted.boundRadius = std::ceil(fitted.boundRadius / digits) * digits;
    std::vector<Formula> candidates{fitted};
    if (fitted.boundRadius != before.boundRadius) {
        candidates.push_back(fitted);
        candidates.back().boundRadius = before.boundRadius;
    }
    std::string rejected;
    for (const Formula& candidate : candidates) {
        const EstimatorMeasurement best = compareEstimators(candidate, preset.camera, options).front();
        if (best.report.samples > 0 && best.hasFactor) {
            f = candidate;
            f.estimator = best.estimator;
            f.deFactor = best.factor;
            std::printf("fit: estimator %s -> %s, bailout %g -> %g, bound radius %g -> %g\n",
                        std::string(before.estimator.block->id).c_str(), std::string(f.estimator.block->id).c_str(),
                        before.bailout, f.bailout, before.boundRadius, f.boundRadius);
            if (!rejected.empty()) std::printf("fit: rejected %s\n", rejected.c_str());
            return true;
        }
        char why[256];
        std::snprintf(why, sizeof why, "%s%s at bailout %g within bound radius %g (%s)", rejected.empty() ? "" : "; ",
                      std::string(candidate.estimator.block->id).c_str(), candidate.bailout, candidate.boundRadius,
                      best.report.samples == 0 ? "no ray of the check meets the object" : "no safe step factor");
        rejected += why;
    }
    std::printf("fit: kept estimator %s, bailout %g, bound radius %g: the fit's candidates were rejected: %s\n",
                std::string(before.estimator.block->id).c_str(), before.bailout, before.boundRadius, rejected.c_str());
    return false;
}

// The factor and the tag of the structure it was measured for (the editor measures a file whose
// tag is not its structure's when it opens it).
std::string withMeasuredFactor(std::string text, const Formula& f, double factor, const std::string& file) {
    text = withNumberInPlace(text, "formula", "deFactor", factor, file);
    return withStringInPlace(text, "formula", "deFactorMeasuredFor", stepFactorTag(f), file);
}

// The fitted formula's estimator, bailout, bound and factor written into the preset file, every
// other byte as it was.
std::string withFittedFormula(std::string text, const Formula& f, double factor, const std::string& file) {
    text = withLastElementInPlace(text, "formula", "nodes", nodeToJson(f.estimator), file);
    text = withNumberInPlace(text, "formula", "bailout", f.bailout, file);
    text = withNumberInPlace(text, "formula", "boundRadius", f.boundRadius, file);
    return withMeasuredFactor(text, f, factor, file);
}

// The preset as checked: the file's, or its animation's frame `o.frame`.
Preset checkedPreset(const CheckOptions& o) { return sceneAtFrame(o.preset, o.frame); }

// GPU (float) against CPU (double) at random points in the bound; the count that agree.
void compareGpuWithCpu(const Formula& f, gl::DEProbe& probe, uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-f.boundRadius, f.boundRadius);
    std::vector<vec3> points(2000);
    for (vec3& p : points) p = randomVec3(u, rng);
    const auto gpu = probe.evaluate(f, points);
    size_t agree = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const double cpu = distanceEstimate(f, points[i]);
        agree += std::abs(gpu[i].distance - cpu) <= 1e-4 * std::max(std::abs(cpu), 0.1);
    }
    // Points that disagree sit where the orbit's escape iteration flips under rounding.
    std::printf("GPU (float) and CPU (double) agree within 1e-4 at %zu of %zu points\n", agree, points.size());
}

// What loading did beyond reading: notes on migrating an older version (not problems: the
// preset is read as the current version), and fields of a newer version that were kept.
void printLoadNotes(const std::vector<std::string>& migrationNotes, const KeptFields& kept, int formatVersion) {
    for (const std::string& note : migrationNotes) std::printf("migrated: %s\n", note.c_str());
    if (!migrationNotes.empty())
        std::printf("migrated: saving writes format version %d (the file itself is not changed)\n", kPresetVersion);
    if (formatVersion > kPresetVersion) {
        std::string fields;
        for (const std::string& field : kept.paths()) fields += (fields.empty() ? "" : ", ") + field;
        std::printf("newer format: the file is version %d, this build reads version %d%s\n", formatVersion,
                    kPresetVersion, fields.empty() ? "" : ("; kept for saving, not read: " + fields).c_str());
    }
}

// A 2D preset: its schema and ranges (by loading it) and its GLSL. Distance-estimate checks are
// for 3D ray marching; the 2D renderer evaluates every sample to the end of its orbit.
int runPlaneCheck(const CheckOptions& o) {
    const PlanePreset preset = loadPlanePreset(o.preset);
    if (o.frame)
        throw std::runtime_error(o.preset + ": --frame " + std::to_string(*o.frame) + ": 2D presets have no animation");
    std::printf("%s: %s (2D)\n", o.preset.c_str(), preset.name.empty() ? "(unnamed)" : preset.name.c_str());
    printLoadNotes(preset.migrationNotes, preset.unknownFields, preset.formatVersion);
    std::printf("formula: %s", describePlaneFormula(preset.formula).c_str());
    std::unique_ptr<gl::HeadlessContext> context;
    try {
        context = gl::HeadlessContext::create();
    } catch (const std::exception& e) {
        std::printf("GLSL: not checked (%s)\nOK\n", e.what());
        return 0;
    }
    try {
        PlaneRenderer renderer;
        renderer.prepare(preset.formula);
        std::printf("GLSL: compiles on %s (%s precision)\n", context->renderer().c_str(),
                    renderer.usesDouble() ? "double" : "single");
        for (const std::string& w : renderer.warnings()) std::printf("warning: %s\n", w.c_str());
    } catch (const std::runtime_error& e) {
        std::printf("PROBLEM: %s\nNOT SOUND\n", e.what());
        return 1;
    }
    std::printf("OK\n");
    return 0;
}

int runCheck(const CheckOptions& o) {
    if (o.apply && isImportedSceneFile(o.preset))
        throw std::runtime_error(o.preset + ": --apply writes into a preset (JSON); import the " +
                                 (frag::isFragPath(o.preset) ? "frag" : "Mandelbulber2 file") +
                                 " first: "
                                 "fraktal import " +
                                 o.preset + " -o PRESET.json" +
                                 (frag::isFragPath(o.preset) ? "" : " (it measures the factor)"));
    if (isPlanePresetFile(o.preset)) {
        if (o.apply) throw std::runtime_error(o.preset + ": --apply: a 2D preset has no step factor");
        return runPlaneCheck(o);
    }
    Preset preset = checkedPreset(o);
    // The factor measured here is the combined estimate's, and one number cannot say which
    // fractal's estimate overshoots: each fractal's own is measured alone (as `fraktal import` does).
    if (o.apply && !preset.formula.fractals.empty())
        throw std::runtime_error(o.preset +
                                 ": --apply: the formula combines whole fractals, each with its own deFactor; the "
                                 "check measures the combination, so set each fractal's factor by hand (or check "
                                 "each fractal alone as a preset of its own)");
    SafeStepOptions safe;
    safe.rays.stepsAcrossBound = o.steps;
    safe.rays.seed = o.seed;
    const Formula fileFormula = preset.formula;
    std::printf("%s: %s", o.preset.c_str(), preset.name.empty() ? "(unnamed)" : preset.name.c_str());
    if (o.frame) std::printf(" at frame %d", *o.frame);
    std::printf("\n");
    printLoadNotes(preset.migrationNotes, preset.unknownFields, preset.formatVersion);
    const bool fitted = o.fit && fitToBlocks(preset, safe);
    const Formula& f = preset.formula;
    std::printf("formula: %s", describeFormula(f).c_str());

    int status = 0;
    std::unique_ptr<gl::HeadlessContext> context;
    try {
        context = gl::HeadlessContext::create();
    } catch (const std::exception& e) {
        if (!f.cpuEvaluable()) throw std::runtime_error(std::string("custom GLSL blocks need OpenGL: ") + e.what());
        std::printf("GLSL: not checked (%s)\n", e.what());
    }
    std::unique_ptr<FormulaSampler> sampler;
    if (context) {
        try {
            if (f.cpuEvaluable()) {
                gl::DEProbe probe(f);
                std::printf("GLSL: compiles on %s\n", context->renderer().c_str());
                compareGpuWithCpu(f, probe, o.seed);
            } else {
                sampler = std::make_unique<gl::GpuSampler>(f);
                std::printf("GLSL: compiles on %s; custom blocks are evaluated there (single precision)\n",
                            context->renderer().c_str());
            }
        } catch (const std::runtime_error& e) {
            std::printf("PROBLEM: %s\nNOT SOUND\n", e.what());
            return 1;
        }
    }
    if (!sampler) sampler = std::make_unique<CpuSampler>(f);

    const GridReport g = evaluateGrid(*sampler, o.grid);
    std::printf("grid %d^3 over the bound: DE in [%.6g, %.6g], %.1f%% inside, %ld non-finite, %.2f us per DE\n", o.grid,
                g.minDistance, g.maxDistance, 100.0 * double(g.inside) / double(g.points), g.nonFinite,
                g.secondsPerEvaluation * 1e6);

    ConservativenessOptions co;
    co.rays = o.rays;
    co.stepsAcrossBound = o.steps;
    co.seed = o.seed;
    const RaySamples samples = sampleRays(*sampler, preset.camera, co);
    const ConservativenessReport c = compareWithSamples(*sampler, samples);
    std::printf(
        "baseline marcher (step %.3g): %d rays, %d hit, %ld samples; worst DE / true distance = %.4f at (%.4f, %.4f, "
        "%.4f)\n",
        2.0 * f.boundRadius / co.stepsAcrossBound, c.rays, c.raysHit, c.samples, c.worstRatio, c.worstPoint.x,
        c.worstPoint.y, c.worstPoint.z);

    if (g.nonFinite > 0) {
        std::printf("PROBLEM: the DE is not finite at %ld grid points\n", g.nonFinite);
        status = 1;
    }
    // Scenes viewed from within (the Kleinian strip, the pseudo-Kleinian lattice) need the camera
    // in their empty part: from inside the object every camera ray hits at once and the image is
    // one colour, while the rays above still count as hits.
    Evaluation atCamera;
    sampler->evaluate(std::span(&preset.camera.position, 1), std::span(&atCamera, 1));
    if (atCamera.inside) {
        std::printf("PROBLEM: the camera is inside the fractal: move camera.position\n");
        status = 1;
    }
    if (c.raysHit == 0) {
        std::printf("PROBLEM: no ray hit the fractal: check the camera and formula.boundRadius\n");
        status = 1;
    } else if (c.samples == 0) {
        // Every hit was at the ray's start (inside already): there is no gap to measure the DE on.
        std::printf("PROBLEM: every ray started inside the fractal: nothing was measured\n");
        status = 1;
    }
    const bool overshoots = !c.conservative();
    if (!overshoots) {
        std::printf("conservative: the DE never overshoots by more than 1%%; step multiplier 1 is safe\n");
    } else {
        std::printf(
            "PROBLEM: the DE overshoots by up to %.1f%%: multiply formula.deFactor by %.3f (or less) "
            "to make marching safe%s\n",
            100.0 * (c.worstRatio - 1.0), 0.99 * c.safeStepMultiplier(), o.apply ? " (--apply: see below)" : "");
    }
    // The step factor the rays allow, with the margin for the rays that were not sampled
    // (core/safe_step.hpp): rays in rounds from this seed until the worst ratio settles, and on
    // while the margin does not cover the worst the rays' tail projects (the editor applies the
    // settled rounds' factor at once and this one when its worker ends). Above the current factor,
    // marching is slower than it needs to be; below it, the current one overshoots.
    const SafeStepRays safeRays = c.samples > 0 ? sampleSafeStepRays(*sampler, preset.camera, safe) : SafeStepRays{};
    const ConservativenessReport& s = safeRays.report;
    const EstimatorMeasurement own = measureSafeStep(f, safeRays, safe);
    if (s.samples > 0 && !hasSafeStepFactor(own)) {
        std::printf(
            "PROBLEM: no step factor down to %g keeps the DE under the distance (worst %.4g at factor 1 over %d "
            "rays, %.4g projected over %g): the estimate is not usable for this stack\n",
            kMinStepFactor, own.report.worstRatio, s.rays, own.projectedWorst, safe.raysAhead);
        status = 1;
    } else if (s.samples > 0 && s.worstRatio > 0.0)
        std::printf(
            "safe step factor: formula.deFactor %.3f (now %.3f; over %d rays, worst DE / true distance %.3f, median "
            "%.3f; at factor 1 the worst %.3f, projected over %g rays %.3f); speed %.4f (factor x median per "
            "orbit)\n",
            own.factor, f.deFactor, s.rays, s.worstRatio, s.medianRatio, own.report.worstRatio, safe.raysAhead,
            own.projectedWorst, own.speed());
    // A useless estimate (far under the distance everywhere: every ray stops at once or crawls)
    // fails; a small factor is explained. Both name what keeps the estimate loose and the
    // estimator the fit would choose; so does a stack with no safe factor or nothing to measure.
    const bool useless = uselessSpeed(own);
    if (useless)
        std::printf("PROBLEM: the estimate is useless: a step covers %.2g%% of the gap (speed %.4f, under %g)\n",
                    100.0 * own.speed(), own.speed(), kUselessSpeed);
    const bool unmeasured = c.raysHit > 0 && (s.samples == 0 || c.samples == 0);
    const bool slow = s.samples > 0 && own.factor < kExplainFactor;
    std::string whyText;  // what keeps the estimate slow, useless or unmeasured, and why
    if (f.cpuEvaluable() && (useless || unmeasured || !hasSafeStepFactor(own) || slow)) {
        const SlowStack why =
            explainSlowStack(f, preset.camera, safe, s.samples > 0 ? std::optional(own) : std::nullopt);
        whyText = why.text(f);
        std::printf("%s: %s\n", useless || unmeasured || !hasSafeStepFactor(own) ? "why" : "note: slow",
                    whyText.c_str());
        if (why.faster)
            std::printf(
                "fix: `fraktal check --fit --apply %s` fits and writes the estimator (%s at bailout %g here), the "
                "bound and the factor it measures for them\n",
                o.preset.c_str(), std::string(why.faster->estimator.block->id).c_str(), why.faster->bailout);
        else if (useless && why.block >= 0)
            std::printf("fix: no estimator the fit offers is faster; change the block named above or its values\n");
        else if (useless)
            std::printf(
                "fix: no estimator the fit offers is faster, and no one block keeps it loose (taking any one out "
                "leaves no object to measure): change the stack, e.g. add a step that scales the orbit up\n");
    }
    if (useless) status = 1;
    // Steps whose map jumps (a non-integer power's atan2 cut, a phase's pole, a wrap): the rays
    // that pass close to a jump are rare, and the overshoot there has no bound, so no number of
    // sampled rays proves a factor (at frame 164, power 9.55, the power morph's estimate reaches
    // 3.75x the distance at factor 1 on 2000 rays, where the rounds of rays see 2.0x).
    for (size_t k = 0; k < f.nodes.size(); ++k)
        if (jumps(f.nodes[k]))
            std::printf(
                "note: step %zu (%s): %s; the factor is measured, not proven; rays that pass close to the jump "
                "may overshoot more than any sampled one (more --rays sample more of them)\n",
                k + 1, std::string(f.nodes[k].block->id).c_str(), std::string(f.nodes[k].block->jump).c_str());
    // The estimators that share the membership (escape-time ones; a primitive and its gradient
    // twin), on the same rays.
    const auto candidates =
        f.cpuEvaluable() && s.samples > 0 ? compareEstimators(f, safeRays, safe) : std::vector<EstimatorMeasurement>{};
    if (candidates.size() > 1) {
        for (const EstimatorMeasurement& m : candidates) {
            char offset[48] = "";
            if (m.estimator.block->id == "escape_linear")
                std::snprintf(offset, sizeof offset, " (offset %.3g)", m.estimator.values[0].x);
            std::printf(
                "estimator %s%s: worst %.3f (projected %.3f), median %.3f at factor 1; safe step factor %.3f; speed "
                "%.3f%s\n",
                std::string(m.estimator.block->id).c_str(), offset, m.report.worstRatio, m.projectedWorst,
                m.report.medianRatio, m.factor, m.speed(),
                &m == &candidates.front() ? "  <- largest factor x median per orbit" : "");
        }
    }
    // --apply writes the factor measured whenever there is one, also where the estimate stays slow,
    // useless or otherwise unsound: the file then marches safely, if slowly, and the check still
    // fails on what remains. Nothing measured (no ray met the object from outside it) or no safe
    // factor (the estimate overshoots more than the smallest factor makes up for) leaves the file
    // as it is.
    bool applied = false;
    if (o.apply) {
        if (s.samples == 0) {
            std::printf(
                "not applied: %s is unchanged: no step factor was measured (no ray met the object from outside "
                "it)\n",
                o.preset.c_str());
        } else if (!hasSafeStepFactor(own)) {
            std::printf(
                "not applied: %s is unchanged: no step factor down to %g keeps this estimate under the "
                "distance\n",
                o.preset.c_str(), kMinStepFactor);
        } else {
            // Rounded down to the printed precision, so that the file never holds more than was measured.
            const double factor = std::max(std::floor(own.factor * 1000.0) / 1000.0, kMinStepFactor);
            const std::string text = readGuardedFile(o.preset);
            if (fitted && f.estimator.block != fileFormula.estimator.block)
                for (const Track& t : preset.animation.tracks)
                    if (const auto target = parseParamTarget(t.target);
                        target && (target->estimator || target->node == f.nodes.size()))
                        throw std::runtime_error(o.preset + ": --fit --apply: the fitted estimator " +
                                                 std::string(f.estimator.block->id) + " replaces " +
                                                 std::string(fileFormula.estimator.block->id) +
                                                 ", whose parameters the animation keys (" + t.target +
                                                 "); fit it in the editor, which drops those tracks");
            if (fitted) {
                writeFileAtomically(o.preset, withFittedFormula(text, f, factor, o.preset));
                std::printf(
                    "applied: estimator %s, bailout %g, bound radius %g and formula.deFactor %.3f written to %s "
                    "(was %s, %g, %g, %.3f)\n",
                    std::string(f.estimator.block->id).c_str(), f.bailout, f.boundRadius, factor, o.preset.c_str(),
                    std::string(fileFormula.estimator.block->id).c_str(), fileFormula.bailout, fileFormula.boundRadius,
                    fileFormula.deFactor);
            } else {
                writeFileAtomically(o.preset, withMeasuredFactor(text, f, factor, o.preset));
                std::printf("applied: formula.deFactor %.3f written to %s (was %.3f)\n", factor, o.preset.c_str(),
                            fileFormula.deFactor);
            }
            applied = true;
            if (useless)
                std::printf("stays useless: at the factor written a step covers %.2g%% of the gap; %s\n",
                            100.0 * own.speed(), whyText.c_str());
            else if (slow)
                std::printf("stays slow: the factor written is under %g; %s\n", kExplainFactor, whyText.c_str());
            if (status != 0 && !useless)
                std::printf("the factor written is safe on the rays measured; the problems above remain\n");
        }
    }
    // An overshooting factor is a problem unless the measured one replaced it.
    if (overshoots && !applied) status = 1;
    std::printf(status == 0 ? "OK\n" : "NOT SOUND\n");
    return status;
}

}  // namespace

Preset sceneAtFrame(const std::string& file, std::optional<int> frame) {
    Preset preset = loadSceneFile(file, headlessGlslSampler());
    if (!frame) return preset;
    const Animation& a = preset.animation;
    if (a.empty())
        throw std::runtime_error(file + ": --frame " + std::to_string(*frame) + ": the preset has no animation");
    if (*frame < a.firstFrame || *frame > a.lastFrame)
        throw std::runtime_error(file + ": --frame " + std::to_string(*frame) + ": outside the animation's frames " +
                                 std::to_string(a.firstFrame) + "-" + std::to_string(a.lastFrame));
    return presetAtFrame(preset, *frame);
}

void addCheckCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand("check", "Validate a preset and measure its distance estimator");
    cmd->add_option("preset", o->preset,
                    "Preset file (JSON), or a Mandelbulber2 (.fract) or Fragmentarium (.frag) file, imported")
        ->required();
    cmd->add_option("--grid", o->grid, "Grid points per axis for the DE survey")->check(CLI::Range(2, 256));
    cmd->add_option("--rays", o->rays, "Rays for the conservativeness check")->check(CLI::Range(1, 100000));
    cmd->add_option("--steps", o->steps,
                    "Baseline march steps across the bound's diameter (finer finds thinner parts; default 4000)")
        ->check(CLI::Range(100, 1000000));
    cmd->add_option("--seed", o->seed, "Random seed");
    cmd->add_option("--frame", o->frame, "Check the preset as its animation has it at this frame");
    cmd->add_flag("--apply", o->apply,
                  "Write the measured safe step factor into the preset (formula.deFactor; the rest of the file as it "
                  "is, atomically); exit 0 when the preset is then sound")
        ->excludes("--frame");
    cmd->add_flag("--fit", o->fit,
                  "First fit the estimator, the bailout and the bound to the blocks as the editor does after a "
                  "structure change, and take the estimator measured fastest for them (with --apply, all written)")
        ->excludes("--frame");
    cmd->callback([&action, o] { action = [o] { return runCheck(*o); }; });
}

}  // namespace fraktal::cli
