#include "app/editor/viewport/thumbnails.hpp"

#include <epoxy/gl.h>

#include <algorithm>

#include "app/editor/document/document.hpp"

namespace fraktal::editor {

namespace {
// Enough frames for every ray of one sample to finish at any steps-per-frame budget the
// preset's march can need (maxSteps / stepsPerFrame, plus the settle frame), bounded.
constexpr int kMaxThumbnailFrames = 64;
constexpr int kPlaneThumbnailSamples = 4;

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

GLuint renderPlaneThumbnail(ThumbnailRenderer& r, const PlanePreset& preset, const ColorPipeline& color) {
    if (!r.plane) r.plane = std::make_unique<PlaneViewport>(color);
    r.plane->setTargetSamples(kPlaneThumbnailSamples);
    r.plane->setReducedWhileMoving(false);  // the copy below needs the full thumbnail size
    // Each call renders a band of a pass within the view's time budget: call until refined.
    for (int call = 0; call < 1024; ++call) {
        r.plane->render(preset, r.width, r.height);
        if (!r.plane->compileError().empty()) throw std::runtime_error(r.plane->compileError());
        if (!r.plane->refining()) break;
    }
    return copyOf(r.plane->displayTexture(), r.width, r.height);
}
}  // namespace

bool renderNextThumbnail(ThumbnailRenderer& r, PresetBrowser& b, const ColorPipeline& color) {
    for (Thumbnail& t : b.entries) {
        if (t.texture || t.failed) continue;
        try {
            if (isPlanePresetFile(t.file)) {
                t.texture = renderPlaneThumbnail(r, loadPlanePreset(t.file), color);
                return true;
            }
            Document d;
            d.preset = loadPreset(t.file);
            loadEditorSection(d);
            if (!r.viewport) r.viewport = makeViewportView(color);
            ViewSettings v = d.view;
            v.aaCap = 1;
            v.pathTraceAtRest = false;  // a thumbnail is the fast image
            v.frameTimeTargetMs = 0.0;  // one viewport renders every thumbnail: each is a new view, at full size
            v.stepsPerFrame = std::max(v.stepsPerFrame, 64);
            for (int frame = 0; frame < kMaxThumbnailFrames; ++frame) {
                r.viewport->render(d.preset, v, r.width, r.height);
                if (!r.viewport->compileError().empty()) throw std::runtime_error(r.viewport->compileError());
                if (r.viewport->stats().settled) break;
            }
            t.texture = copyOf(r.viewport->displayTexture(), r.width, r.height);
        } catch (const std::exception&) {
            t.failed = true;  // shown as "(cannot render)"; opening it reports the reason
        }
        return true;
    }
    return false;
}

void releaseThumbnails(PresetBrowser& b) {
    for (Thumbnail& t : b.entries) {
        if (t.texture) glDeleteTextures(1, &t.texture);
        t.texture = 0;
    }
}

}  // namespace fraktal::editor
