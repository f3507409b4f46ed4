#include "app/editor/viewport/thumbnails.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <chrono>

namespace fraktal::editor {

namespace {
// March steps per ray a thumbnail frame takes: a few milliseconds of llvmpipe at 272x170, so that
// the frame's budget is kept; the frames a thumbnail may take follow from its preset's steps.
constexpr int kThumbnailStepsPerFrame = 16;
constexpr int kMaxThumbnailFrames = 256;
constexpr int kPlaneThumbnailSamples = 4;
constexpr int kMaxPlaneCalls = 1024;

// A texture of its own for the browser (the renderers reuse theirs for the next thumbnail).
GLuint copyOf(GLuint source, int width, int height) {
    GLuint copy = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &copy);
    glTextureStorage2D(copy, 1, GL_RGBA8, width, height);
    glTextureParameteri(copy, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTextureParameteri(copy, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glCopyImageSubData(source, GL_TEXTURE_2D, 0, 0, 0, 0, copy, GL_TEXTURE_2D, 0, 0, 0, 0, width, height, 1);
    return copy;
}

Thumbnail* findEntry(PresetBrowser& b, const std::filesystem::path& file) {
    for (Thumbnail& t : b.entries)
        if (t.file == file && !t.texture && !t.failed) return &t;
    return nullptr;
}

// Starts the next missing thumbnail: its document loaded, nothing rendered yet.
Thumbnail* startNext(ThumbnailRenderer& r, PresetBrowser& b) {
    for (Thumbnail& t : b.entries) {
        if (t.texture || t.failed) continue;
        r.file = t.file;
        r.frames = 0;
        try {
            r.document = Document();
            if (isPlanePresetFile(t.file)) {
                r.document.plane = loadPlanePreset(t.file);
            } else {
                r.document.preset = loadPreset(t.file);
                loadEditorSection(r.document);
            }
        } catch (const std::exception&) {
            t.failed = true;  // shown as "(cannot render)"; opening it reports the reason
            r.file.clear();
            continue;
        }
        return &t;
    }
    r.file.clear();
    return nullptr;
}

// One step of a 2D thumbnail: a band of a pass within the plane view's own time budget.
// Returns the finished texture, or 0 while it refines.
GLuint stepPlaneThumbnail(ThumbnailRenderer& r, const ColorPipeline& color) {
    if (!r.plane) r.plane = std::make_unique<PlaneViewport>(color);
    if (r.frames == 0) {
        r.plane->setTargetSamples(kPlaneThumbnailSamples);
        r.plane->setReducedWhileMoving(false);  // the copy below needs the full thumbnail size
    }
    r.plane->render(*r.document.plane, r.width, r.height);
    ++r.frames;
    if (!r.plane->compileError().empty()) throw std::runtime_error(r.plane->compileError());
    if (r.plane->refining() && r.frames < kMaxPlaneCalls) return 0;
    return copyOf(r.plane->displayTexture(), r.width, r.height);
}

// One frame of a 3D thumbnail. Returns the finished texture, or 0 while it compiles or marches.
GLuint stepThumbnail(ThumbnailRenderer& r, const ColorPipeline& color) {
    if (!r.viewport) r.viewport = makeViewportView(color, r.compiler.get());
    ViewSettings v = r.document.view;
    v.aaCap = 1;
    v.pathTraceAtRest = false;  // a thumbnail is the fast image
    v.frameTimeTargetMs = 0.0;  // one viewport renders every thumbnail: each is a new view, at full size
    v.stepsPerFrame = kThumbnailStepsPerFrame;
    r.viewport->render(r.document.preset, v, r.width, r.height);
    if (!r.viewport->compileError().empty()) throw std::runtime_error(r.viewport->compileError());
    if (r.viewport->stats().compiling) return 0;  // the worker compiles; the frame goes on
    ++r.frames;
    // Enough frames for every ray of one sample to finish (maxSteps / steps per frame, plus the
    // settle frame), bounded.
    const int frames = std::min(kMaxThumbnailFrames, r.document.preset.render.maxSteps / kThumbnailStepsPerFrame + 2);
    if (!r.viewport->stats().settled && r.frames < frames) return 0;
    return copyOf(r.viewport->displayTexture(), r.width, r.height);
}
}  // namespace

bool renderNextThumbnail(ThumbnailRenderer& r, PresetBrowser& b, const ColorPipeline& color) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    auto spentMs = [&] { return std::chrono::duration<double, std::milli>(Clock::now() - start).count(); };
    while (spentMs() < r.budgetMs) {
        Thumbnail* t = r.file.empty() ? nullptr : findEntry(b, r.file);
        if (!t) t = startNext(r, b);
        if (!t) return false;
        try {
            const GLuint texture = r.document.plane ? stepPlaneThumbnail(r, color) : stepThumbnail(r, color);
            if (!texture) {
                // Compiling in the background: nothing more to do this frame.
                if (!r.document.plane && r.viewport->stats().compiling) return true;
                continue;
            }
            t->texture = texture;
        } catch (const std::exception&) {
            t->failed = true;  // shown as "(cannot render)"; opening it reports the reason
        }
        r.file.clear();
    }
    return true;
}

void releaseThumbnails(PresetBrowser& b) {
    for (Thumbnail& t : b.entries) {
        if (t.texture) glDeleteTextures(1, &t.texture);
        t.texture = 0;
    }
}

}  // namespace fraktal::editor
