#include "core/viewport/viewport.hpp"

namespace fraktal::viewport {

namespace {
int64_t pixels(const MarchState& s) { return int64_t(s.width()) * s.height(); }
}  // namespace

Viewport::Viewport(ViewportOptions options) : options_(options) {
    counters_ = std::make_unique<GpuCounters>();
    timer_ = std::make_unique<PassTimer>();
    glCreateVertexArrays(1, &displayVertexArray_);
}

Viewport::~Viewport() {
    glDeleteFramebuffers(2, resampleFramebuffers_);
    glDeleteVertexArrays(1, &displayVertexArray_);
}

void Viewport::setOptions(const ViewportOptions& options) {
    if (options.coneTile != options_.coneTile) {
        state_.reset();  // the cone image's size depends on the tile
        spareGrid_.reset();
        forceReset_ = true;
    }
    if (options.overRelaxation != options_.overRelaxation) forceReset_ = true;
    options_ = options;
}

FrameKey Viewport::frameKey(const Formula& formula, const Camera& camera, const RenderSettings& render,
                            const ShadingSettings& shading, int width, int height, const ThinLens& lens,
                            const scene::SceneRevision* revision) const {
    RenderSettings effective = render;
    if (!options_.overRelaxation) {
        effective.overRelaxation = 1.0;
        effective.maxStepGrowth = 1.0;
    }
    const ShadingParams params = resolveShading(shading, effective, formula);
    return FrameKey{width,
                    height,
                    revision ? revision->structure : formula.structureKey(),
                    revision ? revision->values : formulaValuesKey(formula),
                    params,
                    render.maxSteps,
                    camera,
                    lens};
}

FrameStats Viewport::render(const Formula& formula, const Camera& camera, const RenderSettings& render,
                            const ShadingSettings& shading, int width, int height, const ThinLens& lens,
                            const scene::SceneRevision* revision) {
    if (width < 2 || height < 2) throw std::runtime_error("viewport: size must be at least 2x2");
    FrameKey key = frameKey(formula, camera, render, shading, width, height, lens, revision);
    const ShadingParams& params = key.shading;
    // Compile first: if it fails, the old programs and image stay.
    if (needsPrograms(key.structure)) programs_ = std::make_unique<ViewportPrograms>(formula);
    // A new size keeps the previous grid for this frame: a reprojected frame scatters its points
    // into the new grid, and every pixel not yet finished shows the previous image, upsampled.
    std::unique_ptr<MarchState> previousGrid;
    if (!state_ || state_->width() != width || state_->height() != height) {
        previousGrid = std::move(state_);
        // Back to the size of the grid motion left (the view at rest again): that grid, whose rays
        // are of an older view and start again (MarchState::generation), instead of a new one.
        if (spareGrid_ && spareGrid_->width() == width && spareGrid_->height() == height)
            state_ = std::move(spareGrid_);
        else
            state_ = std::make_unique<MarchState>(width, height, options_.coneTile);
        if (spareGrid_ && pixels(*spareGrid_) <= pixels(*state_)) spareGrid_.reset();  // no use any more
        if (previousGrid) {
            resampleInto(*previousGrid, &MarchState::image, *state_);
            resampleInto(*previousGrid, &MarchState::shown, *state_);
        } else {
            const float black[4] = {0, 0, 0, 1};
            glClearTexImage(state_->image, 0, GL_RGBA, GL_FLOAT, black);
            glClearTexImage(state_->shown, 0, GL_RGBA, GL_FLOAT, black);
        }
    }

    FrameAction decided =
        forceReset_ ? FrameAction::Reset
                    : decideFrame(previous_ ? &*previous_ : nullptr, key, options_.reproject, previousAction_);
    forceReset_ = false;
    // The caller slices this frame (a frame at rest) and the grid changed with the camera still:
    // motion on a smaller grid just stopped. Reprojected (decideFrame's choice for a size change
    // under motion), every ray of the full-size view would march in this one frame, unsliced:
    // 650-700 ms on light scenes in the editor on llvmpipe (bench/viewport/README.md). A sliced
    // reset refines it over the next frames, over the previous image resampled.
    if (decided == FrameAction::Reproject && options_.slices > 1 && previousGrid && previous_->camera == camera)
        decided = FrameAction::Reset;
    // A held frame marches on like a continued one; only its decision (it never settles, and
    // the next still frame resets) differs.
    const FrameAction action = decided == FrameAction::Hold ? FrameAction::Continue : decided;
    if (action == FrameAction::Continue && settled_) {
        FrameStats idle = summarize(FrameCounters{0, 0, 0, uint64_t(width) * height, 0}, width, height, action);
        idle.settled = true;
        return idle;
    }

    FrameContext context{formula, camera, params, options_, render.maxSteps, action == FrameAction::Continue, lens};
    // Sliced refinement: at rest and on a reset, never on a reprojected frame (its starts are
    // verified by their first step, which every pixel needs this frame).
    if (options_.slices > 1 && action != FrameAction::Reproject) {
        context.sliceCount = options_.slices;
        context.sliceIndex = sliceOfFrame(slicedFrames_, options_.slices);
        slicedFrames_ = (slicedFrames_ + 1) % (1 << 20);  // a whole cycle of any power of two up to 2^20
    }
    const bool timed = options_.timePasses;
    auto mark = [&](const char* pass) {
        if (timed) timer_->mark(pass);
    };
    if (timed) timer_->begin();
    counters_->clearAndBind();
    state_->bindLists();
    if (action == FrameAction::Reproject) {
        runReprojectPass(*programs_, previousGrid ? *previousGrid : *state_, *state_, previous_->camera, camera);
        mark("reproject");
    }
    // A new view's rays: numbered after the reprojection, which reads the old view's.
    if (action != FrameAction::Continue) {
        generation_ = generation_ % kMaxGeneration + 1;
        state_->generation = generation_;
    }
    // (A sliced reset's rays start slice by slice from the camera, past no cone.)
    if (action != FrameAction::Continue && options_.coneTile > 0 && context.sliceCount <= 1) {
        runConePass(*programs_, *state_, context);
        mark("cone");
    }
    runMarchPass(*programs_, *state_, context, action);
    mark("march");
    runMarchListPass(*programs_, *state_, context, action);
    mark("march_list");
    runShadePass(*programs_, *state_, context);
    mark("shade");
    runAccumulatePass(*programs_, *state_, context);
    mark("accumulate");
    runResolvePass(*programs_, *state_, context);
    mark("resolve");

    FrameCounters counts = counters_->read();
    // On a new view every pixel either reprojected or restarted; the march pass counts only the first.
    if (action != FrameAction::Continue) counts.restarted = uint64_t(width) * height - counts.reprojected;
    counts.marchListed = state_->marchListCount();
    // A sliced frame counted its slice alone: the view's counts are the slices' last ones.
    sliceProgress_.record(action != FrameAction::Continue, context.sliceCount, context.sliceIndex,
                          counters_->busyPixels(), counts.converged);
    counts.converged = sliceProgress_.convergedPixels();
    FrameStats stats = summarize(counts, width, height, decided);
    stats.slices = context.sliceCount;
    if (timed) stats.passTimes = timer_->read();
    settled_ = decided == FrameAction::Continue && sliceProgress_.settled();
    stats.settled = settled_;
    // Motion went to a smaller grid: the larger one it left is kept for the return to rest (a new
    // grid of 690x520 took 60 ms to allocate, most of the first frame at rest on llvmpipe).
    if (previousGrid && pixels(*previousGrid) > pixels(*state_) && !spareGrid_) spareGrid_ = std::move(previousGrid);
    previous_ = std::move(key);
    previousAction_ = decided;
    return stats;
}

bool Viewport::hasGrid(int width, int height) const {
    const auto sized = [&](const std::unique_ptr<MarchState>& grid) {
        return grid && grid->width() == width && grid->height() == height;
    };
    return sized(state_) || sized(spareGrid_);
}

void Viewport::adoptSpareGrid(std::unique_ptr<MarchState> grid) {
    if (grid && grid->coneTile() == options_.coneTile) spareGrid_ = std::move(grid);
}

void Viewport::resampleInto(const MarchState& from, GLuint MarchState::*texture, const MarchState& to) {
    if (!resampleFramebuffers_[0]) glCreateFramebuffers(2, resampleFramebuffers_);
    glNamedFramebufferTexture(resampleFramebuffers_[0], GL_COLOR_ATTACHMENT0, from.*texture, 0);
    glNamedFramebufferTexture(resampleFramebuffers_[1], GL_COLOR_ATTACHMENT0, to.*texture, 0);
    glBlitNamedFramebuffer(resampleFramebuffers_[0], resampleFramebuffers_[1], 0, 0, from.width(), from.height(), 0, 0,
                           to.width(), to.height(), GL_COLOR_BUFFER_BIT, GL_LINEAR);
}

void Viewport::drawDisplay(float exposure) {
    if (!state_) return;
    runDisplayPass(*programs_, *state_, exposure, true, displayVertexArray_);
}

std::vector<float> Viewport::readState(GLuint MarchState::*texture) const {
    if (!state_) return {};
    std::vector<float> pixels(size_t(state_->width()) * state_->height() * 4);
    glGetTextureImage((*state_).*texture, 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)), pixels.data());
    return pixels;
}

std::vector<float> Viewport::readImage() const { return readState(&MarchState::shown); }

std::vector<float> Viewport::readCentreRays() const { return readState(&MarchState::centre); }

std::vector<float> Viewport::readColourPoints() const { return readState(&MarchState::colourPoint); }

std::vector<uint8_t> Viewport::readDisplay(float exposure) {
    if (!state_) return {};
    const int w = state_->width(), h = state_->height();
    display_.resize(w, h);
    GLint previousFramebuffer = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previousFramebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, display_.framebuffer());
    glViewport(0, 0, w, h);
    runDisplayPass(*programs_, *state_, exposure, false, displayVertexArray_);
    glBindFramebuffer(GL_FRAMEBUFFER, GLuint(previousFramebuffer));
    std::vector<uint8_t> pixels(size_t(w) * h * 4);
    glGetTextureImage(display_.texture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    return pixels;
}

}  // namespace fraktal::viewport
