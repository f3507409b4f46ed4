#include "app/editor/viewport/viewport_adapter.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace fraktal::editor {

std::unique_ptr<ViewportView> makeViewportView(const ColorPipeline& color, BackgroundCompiler* compiler) {
    return std::make_unique<CoreViewportView>(color, compiler);
}

viewport::ViewportOptions viewportOptions(const ViewSettings& v) {
    viewport::ViewportOptions o;
    o.stepsPerFrame = v.stepsPerFrame;
    o.maxSamples = v.aaCap;
    o.reproject = v.reprojection;
    o.coneTile = v.coneTile;
    o.maxCarryFrames = v.maxCarryFrames;
    o.motionFilter = v.motionFilter;
    o.motionFilterRadius = v.motionFilterRadius;
    o.coarseHits = v.coarseHits;
    return o;
}

ShadingSettings shadingInWorkingSpace(const ShadingSettings& shading, const ColorPipeline& color,
                                      const std::string& workingSpace) {
    // The colours core/shading_params.cpp converts (the palette's c and d are frequencies
    // and phases, and its a and b multiply the light, so they stay as written, as in the still).
    ShadingSettings s = shading;
    for (vec3* c : {&s.lightColor, &s.fillColor, &s.fogColor, &s.backgroundTop, &s.backgroundBottom})
        *c = color.fromLinearRec709(*c, workingSpace);
    return s;
}

namespace {

bool sameOptions(const viewport::ViewportOptions& a, const viewport::ViewportOptions& b) {
    return a.stepsPerFrame == b.stepsPerFrame && a.slices == b.slices && a.maxSamples == b.maxSamples &&
           a.reproject == b.reproject && a.overRelaxation == b.overRelaxation && a.coneTile == b.coneTile &&
           a.coneSteps == b.coneSteps && a.maxCarryFrames == b.maxCarryFrames && a.motionFilter == b.motionFilter &&
           a.motionFilterRadius == b.motionFilterRadius && a.coarseHits == b.coarseHits;
}

}  // namespace

CoreViewportView::CoreViewportView(const ColorPipeline& color, BackgroundCompiler* compiler)
    : color_(color), compiler_(compiler) {}

bool CoreViewportView::programsReady(const Formula& formula, const std::string& structure) {
    stats_.compiling = false;
    if (!compiler_ || !viewport_.needsPrograms(structure)) return true;
    std::optional<BackgroundCompiler::Result> result = compiler_->take(structure);
    if (!result) {
        compiler_->request(formula);
        stats_.compiling = true;
        // The image shown is the old structure's: not the settled picture of this document.
        stats_.settled = false;
        return false;
    }
    if (!result->programs) {
        // The viewport keeps its previous programs and image; the node's error is shown.
        compileError_ = result->error;
        failedStructure_ = structure;
        return false;
    }
    viewport_.adoptPrograms(std::move(result->programs));
    return true;
}

void CoreViewportView::prepare(const Formula& formula, const std::string& structure) {
    stats_.settled = false;
    if (compiler_ && viewport_.needsPrograms(structure) && structure != failedStructure_) {
        compiler_->request(formula);
        stats_.compiling = true;
    }
}

CoreViewportView::~CoreViewportView() { glDeleteFramebuffers(1, &pathReadFramebuffer_); }

const ShadingSettings& CoreViewportView::workingShading(const Preset& preset) {
    if (!shadingKey_ || shadingKey_->first != preset.shading || shadingKey_->second != preset.render.workingSpace) {
        workingShading_ = shadingInWorkingSpace(preset.shading, color_, preset.render.workingSpace);
        shadingKey_.emplace(preset.shading, preset.render.workingSpace);
    }
    return workingShading_;
}

const Formula& CoreViewportView::workingFormula(const Preset& preset) {
    const Formula& formula = preset.formula;
    if (formula.objects.empty()) return formula;
    std::vector<vec3> colors;
    for (const SceneObject& o : formula.objects) colors.push_back(o.color);
    if (!objectColorsKey_ || objectColorsKey_->first != colors ||
        objectColorsKey_->second != preset.render.workingSpace) {
        workingObjectColors_.clear();
        for (const vec3& c : colors)
            workingObjectColors_.push_back(color_.fromLinearRec709(c, preset.render.workingSpace));
        objectColorsKey_.emplace(std::move(colors), preset.render.workingSpace);
    }
    if (workingObjectColors_ == objectColorsKey_->first) return formula;
    workingFormula_ = formula;
    for (size_t k = 0; k < workingFormula_.objects.size(); ++k)
        workingFormula_.objects[k].color = workingObjectColors_[k];
    return workingFormula_;
}

bool CoreViewportView::renderFrame(const Preset& preset, const scene::SceneRevision& revision,
                                   const ViewSettings& settings, int width, int height) {
    const Formula& formula = preset.formula;
    // Sliced refinement: the last frame's measurement (with the editor's whole frame around it:
    // the UI, the display, the swap hold the window too), then this frame's slices. Only at full
    // size and at rest: under motion the dynamic resolution holds the target, and every frame
    // there marches the whole (smaller) view.
    if (revision.structure != slicedStructure_) {
        restSlices_.forgetNewView();
        slicedStructure_ = revision.structure;
    }
    if (lastRefined_) {
        lastRefined_->frameMs = previousFrameMs_;
        restSlices_.measure(*lastRefined_);
        lastRefined_.reset();
    }
    const bool newView =
        lastAction_ != viewport::FrameAction::Continue || viewport_.width() != width || viewport_.height() != height;
    const bool sliced =
        sliceAtRest_ && settings.frameTimeTargetMs > 0.0 && resolution_.scale() == 1.0 && !resolution_.moving();
    const double restTargetMs = std::max(settings.frameTimeTargetMs, viewport::kRestFrameTargetMs);
    lastAction_ = viewport::FrameAction::Reset;
    if (!failedStructure_.empty() && revision.structure == failedStructure_) return false;
    viewport::ViewportOptions options = viewportOptions(settings);
    if (sliced)
        options.slices = restSlices_.choose(newView, restTargetMs,
                                            std::min(viewport::kMaxRestSlices, viewport::viewTiles(width, height)));
    if (!sameOptions(options, viewport_.options())) viewport_.setOptions(options);
    workingShading(preset);
    // A structure the viewport has no programs for: adopted from the background compiler below,
    // or compiled by render() where there is none.
    const bool newStructure = viewport_.needsPrograms(revision.structure);
    if (!programsReady(formula, revision.structure)) return false;
    const auto start = std::chrono::steady_clock::now();
    viewport::FrameStats frame;
    try {
        frame = viewport_.render(workingFormula(preset), preset.camera, preset.render, workingShading_, width, height,
                                 preset.lighting.lens, &revision);
    } catch (const std::exception& e) {
        // The viewport keeps its previous programs and image (viewport.hpp).
        compileError_ = e.what();
        if (newStructure) failedStructure_ = revision.structure;
        return false;
    }
    if (newStructure) ++stats_.compiles;
    compileError_.clear();
    failedStructure_.clear();
    lastAction_ = frame.action;

    const bool idle = frame.settled && frame.action == viewport::FrameAction::Continue && frame.deEvalsPerPixel == 0.0;
    stats_.renderMs =
        idle ? 0.0 : std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    // A frame that refined the view (a reset under motion too: it measures a new view's cost).
    if (!idle && sliceAtRest_ && (sliced || frame.action == viewport::FrameAction::Reset))
        lastRefined_ = viewport::RestFrame{frame.action == viewport::FrameAction::Reset, frame.slices,
                                           resolution_.scale(), stats_.renderMs, 0.0};
    stats_.stepsPerFrame = options.stepsPerFrame;
    stats_.slices = frame.slices;
    stats_.deEvaluationsPerPixel = frame.deEvalsPerPixel;
    stats_.reprojectedShare = frame.shareReprojected;
    stats_.convergedShare = frame.shareConverged;
    stats_.action = viewport::toString(frame.action);
    stats_.aaCap = settings.aaCap;
    // Settled only at full size: a view at rest refines there.
    stats_.settled = frame.settled && resolution_.scale() == 1.0;
    stats_.aaLevel = frame.settled ? settings.aaCap : frame.samplesAtRest + 1;
    stats_.width = width;
    stats_.height = height;
    return !idle;
}

void CoreViewportView::ensureDisplayTarget(int width, int height) {
    if (displayTarget_.resize(width, height)) shownDisplay_.reset();
}

void CoreViewportView::redisplay(const Preset& preset, GLuint linearImage, double gainStops) {
    const DisplayKey key{preset.render.workingSpace, preset.render.display, preset.render.view};
    try {
        display_.configure(color_, key);
        displayError_.clear();
    } catch (const std::exception& e) {
        // A bad view keeps the last good transform on screen; the Render tab shows why.
        displayError_ = e.what();
        if (!display_.configured()) return;
    }
    const auto shown = std::make_pair(display_.key(), preset.render.exposure + gainStops);
    if (!imageChanged_ && shownDisplay_ == shown) return;
    {
        const DisplayTarget::Binding bound = displayTarget_.bind();
        display_.draw(linearImage, preset.render.exposure + gainStops);
    }
    shownDisplay_ = shown;
    imageChanged_ = false;
}

double CoreViewportView::chooseScale(const scene::SceneRevision& revision, const ViewSettings& settings) {
    // Motion: anything the image is rendered from changed (a new display transform is not).
    const scene::SceneChange change = scene::sceneChange(lastView_ ? &*lastView_ : nullptr, revision);
    // Against the last view rendered: a view not rendered yet (the first, or one whose programs
    // are still compiling) is a change, so that it opens as a small whole view that the refinement
    // at full size then shows under its slices, as after any motion. Opened at rest, its slices
    // refined over black for seconds (kifs_coloured_lights: 2 % converged after 7 s at 64 slices).
    const bool changed = !lastView_ || change.restarts() || change.camera;
    // The editor's frame time: from the start of the previous frame's render to this one's.
    const auto now = std::chrono::steady_clock::now();
    const double frameMs =
        lastFrameStart_ ? std::chrono::duration<double, std::milli>(now - *lastFrameStart_).count() : 0.0;
    lastFrameStart_ = now;
    previousFrameMs_ = frameMs;
    viewport::ResolutionControl control = resolution_.control();
    control.targetMs = settings.frameTimeTargetMs;
    control.minScale = settings.motionMinScale;
    resolution_.setControl(control);
    resolution_.seedFullFrameMs(restSlices_.wholeViewMs());
    // Only a frame that rendered measures the cost of one: while a structure compiles, frames of
    // the panels alone (about 10 ms) had taught the controller that a whole view was cheap, and
    // the first picture of every opened preset came at full size, unsliced (0.6-0.9 s).
    return resolution_.next(changed, previousFrameRendered_ ? frameMs : 0.0);
}

void CoreViewportView::render(const Preset& preset, const scene::SceneRevision& revision, const ViewSettings& settings,
                              int fullWidth, int fullHeight) {
    // What changed since the last frame is decided on `revision`, once, by every consumer below.
    if (path_ && !pathStillValid(revision, settings, fullWidth, fullHeight)) dropPath();
    if (path_) {
        lastRefined_.reset();            // a path-traced frame says nothing about the fast mode's slices
        previousFrameRendered_ = false;  // nor about its motion's cost
        pathFrame(preset, settings);
        return;
    }
    stats_.pathTracing = false;
    stats_.pathSamples = 0;
    stats_.pathSppCap = settings.pathSppCap;
    const double scale = chooseScale(revision, settings);
    const int width = std::max(int(std::lround(fullWidth * scale)), 2);
    const int height = std::max(int(std::lround(fullHeight * scale)), 2);
    stats_.internalScale = scale;
    // The grid at full size is made ahead on the worker (asked for before any compile this frame
    // may ask for, which the worker then does after it), and kept as the viewport's spare.
    const BackgroundCompiler::GridSize fullGrid{fullWidth, fullHeight, viewportOptions(settings).coneTile};
    const bool gridWanted = compiler_ && !viewport_.hasGrid(fullWidth, fullHeight);
    if (gridWanted) compiler_->requestGrid(fullGrid);
    previousFrameRendered_ = false;
    try {
        if (renderFrame(preset, revision, settings, width, height)) {
            imageChanged_ = true;
            lastView_ = revision;
            previousFrameRendered_ = true;
        }
    } catch (const std::exception& e) {
        lastAction_ = viewport::FrameAction::Reset;
        displayError_ = e.what();  // e.g. an unknown working space
    }
    // Every grid the worker finishes is taken: kept while the viewport has none of the full size,
    // freed otherwise (one the viewport no longer needs, having made its own first or left that
    // size, would hold about 90 MB at 690x520 until the next resize).
    if (compiler_)
        if (std::unique_ptr<viewport::MarchState> grid = compiler_->takeGrid();
            grid && BackgroundCompiler::GridSize{grid->width(), grid->height(), grid->coneTile()} == fullGrid &&
            !viewport_.hasGrid(fullWidth, fullHeight))
            viewport_.adoptSpareGrid(std::move(grid));
    if (!viewport_.imageTexture()) return;
    ensureDisplayTarget(viewport_.width(), viewport_.height());
    redisplay(preset, viewport_.imageTexture());
    if (!pathError_.empty()) displayError_ = pathError_;
    // The view rests when the fast mode's own decision (decideFrame) continues a full-size frame:
    // nothing changed since the last one. The next frames path-trace it.
    const bool atRest = lastAction_ == viewport::FrameAction::Continue && scale == 1.0 &&
                        viewport_.width() == fullWidth && viewport_.height() == fullHeight;
    if (settings.pathTraceAtRest && atRest && compileError_.empty() && !stats_.compiling) {
        startPath(preset, revision, fullWidth, fullHeight);
        if (path_) stats_.settled = false;  // samples to come: the editor keeps drawing frames
    }
}

bool CoreViewportView::pathStillValid(const scene::SceneRevision& revision, const ViewSettings& settings, int width,
                                      int height) {
    if (!settings.pathTraceAtRest || !failedStructure_.empty()) return false;
    // Everything the scene holds (lights, lens, environment, the background's transparency
    // included: the fast mode does not see them all), the size, and the file that environment
    // paths are relative to. A new display transform only redisplays the samples.
    const PathAtRest& p = *path_;
    const scene::SceneChange change = scene::sceneChange(&p.revision, revision);
    return !change.restarts() && !change.camera && p.render.width == width && p.render.height == height &&
           p.presetFile == presetFile_;
}

void CoreViewportView::startPath(const Preset& preset, const scene::SceneRevision& revision, int width, int height) {
    const std::string failureKey = presetFile_ + "\n" + revision.structure;
    if (pathFailed_ && pathFailed_->first == preset.lighting && pathFailed_->second == failureKey) return;
    PathAtRest p;
    p.revision = revision;
    p.presetFile = presetFile_;
    p.render = preset.render;
    p.render.width = width;
    p.render.height = height;
    try {
        pathData_ = resolvePathScene(preset, presetFile_, color_, pathData_ ? &*pathData_ : nullptr);
        if (!pathTracer_ || pathTracer_->width() != width || pathTracer_->height() != height ||
            pathTracer_->structure() != revision.structure)
            pathTracer_ = std::make_unique<gl::PathTracer>(preset.formula, width, height);
        pathTracer_->setScene(pathData_->scene(preset, p.render));
    } catch (const std::exception& e) {
        // The fast mode stays on screen and the Render tab says why.
        pathError_ = std::string("path tracing at rest: ") + e.what();
        displayError_ = pathError_;
        pathFailed_.emplace(preset.lighting, failureKey);
        pathTracer_.reset();
        return;
    }
    pathError_.clear();
    pathFailed_.reset();
    path_ = std::move(p);
}

void CoreViewportView::copyPathImage() {
    // The tracer's sums, rows flipped to the viewport's order (top row first); the division by
    // the sample count is a gain of -log2(spp) stops in the display pass (both linear).
    const gl::PathTracer& tracer = *pathTracer_;
    const int w = tracer.width(), h = tracer.height();
    pathImage_.resize(w, h);
    if (!pathReadFramebuffer_) glCreateFramebuffers(1, &pathReadFramebuffer_);
    glNamedFramebufferTexture(pathReadFramebuffer_, GL_COLOR_ATTACHMENT0, tracer.beautySumTexture(), 0);
    glBlitNamedFramebuffer(pathReadFramebuffer_, pathImage_.framebuffer(), 0, 0, w, h, 0, h, w, 0, GL_COLOR_BUFFER_BIT,
                           GL_NEAREST);
    imageChanged_ = true;
}

void CoreViewportView::pathFrame(const Preset& preset, const ViewSettings& settings) {
    using Clock = std::chrono::steady_clock;
    const auto ms = [](Clock::time_point a, Clock::time_point b) {
        return std::chrono::duration<double, std::milli>(b - a).count();
    };
    gl::PathTracer& tracer = *pathTracer_;
    const int cap = settings.pathSppCap, h = tracer.height();
    // A frame path-traces for up to three frame-time targets (100 ms by default) in bands of rows,
    // so the window answers within about that even when one sample pass of the whole view takes
    // seconds (llvmpipe). Three, not one: the editor's own work (panels, display, swap) takes
    // 10-20 ms a frame on an idle 2-core llvmpipe machine and about 48 ms under load
    // (bench/README.md, dynamic resolution), so a budget of one 33 ms target could leave the
    // samples half of the time or less. Target 0: a whole pass per frame.
    const double budgetMs = 3.0 * settings.frameTimeTargetMs;
    const auto start = Clock::now();
    int draws = 0;
    while (tracer.samplesTaken() < cap) {
        int rows = h;
        if (budgetMs > 0.0) {
            const double left = budgetMs - ms(start, Clock::now());
            if (draws > 0 && (pathMsPerRow_ <= 0.0 || left < pathMsPerRow_)) break;
            // The first band ever is a probe of 8 rows; then as many rows as the time left holds.
            rows = pathMsPerRow_ > 0.0 ? std::max(int(left / pathMsPerRow_), 1) : 8;
        }
        rows = std::min(rows, h - tracer.rowsDone());
        const auto t0 = Clock::now();
        const bool completed = tracer.addSampleRows(rows);
        ++draws;
        // Rows cost unevenly (background against fractal): a running mean of the recent bands.
        const double perRow = ms(t0, Clock::now()) / rows;
        pathMsPerRow_ = pathMsPerRow_ > 0.0 ? 0.5 * (pathMsPerRow_ + perRow) : perRow;
        if (completed) copyPathImage();  // the sums hold whole passes only now
        if (budgetMs <= 0.0) break;
    }
    stats_.pathTracing = true;
    stats_.pathSamples = tracer.samplesTaken();
    stats_.pathSppCap = cap;
    stats_.settled = tracer.samplesTaken() >= cap;
    stats_.renderMs = draws ? ms(start, Clock::now()) : 0.0;
    stats_.action = "path";
    stats_.internalScale = 1.0;
    stats_.width = tracer.width();
    stats_.height = h;
    if (tracer.samplesTaken() == 0) return;  // the fast image stays until the first whole pass
    ensureDisplayTarget(tracer.width(), h);
    redisplay(preset, pathImage_.texture(), -std::log2(double(tracer.samplesTaken())));
}

void CoreViewportView::dropPath() {
    path_.reset();
    imageChanged_ = true;     // the fast image replaces the path-traced one
    lastFrameStart_.reset();  // the last path-traced frame's time says nothing about a fast frame
}

}  // namespace fraktal::editor
