#include "app/editor/thumbnails.hpp"

#include <epoxy/gl.h>

#include <algorithm>

#include "app/editor/document.hpp"

namespace fraktal::editor {

namespace {
// Enough frames for every ray of one sample to finish at any steps-per-frame budget the
// preset's march can need (maxSteps / stepsPerFrame, plus the settle frame), bounded.
constexpr int kMaxThumbnailFrames = 64;
}  // namespace

bool renderNextThumbnail(ThumbnailRenderer& r, PresetBrowser& b, const ColorPipeline& color) {
    for (Thumbnail& t : b.entries) {
        if (t.texture || t.failed) continue;
        try {
            Document d;
            d.preset = loadPreset(t.file);
            loadEditorSection(d);
            if (!r.viewport) r.viewport = makeViewportView(color);
            ViewSettings v = d.view;
            v.aaCap = 1;
            v.stepsPerFrame = std::max(v.stepsPerFrame, 64);
            for (int frame = 0; frame < kMaxThumbnailFrames; ++frame) {
                r.viewport->render(d.preset, v, r.width, r.height);
                if (!r.viewport->compileError().empty()) throw std::runtime_error(r.viewport->compileError());
                if (r.viewport->stats().settled) break;
            }
            GLuint copy = 0;
            glCreateTextures(GL_TEXTURE_2D, 1, &copy);
            glTextureStorage2D(copy, 1, GL_RGBA8, r.width, r.height);
            glTextureParameteri(copy, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
            glTextureParameteri(copy, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
            glCopyImageSubData(r.viewport->displayTexture(), GL_TEXTURE_2D, 0, 0, 0, 0, copy, GL_TEXTURE_2D, 0, 0, 0, 0,
                               r.width, r.height, 1);
            t.texture = copy;
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
