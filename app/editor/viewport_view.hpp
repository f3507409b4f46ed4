// What the editor needs from a viewport renderer, kept small so the renderer behind it can be
// swapped: today the interim PreviewViewport (preview_viewport.cpp); core/viewport's
// progressive, reprojecting Viewport once it lands (TODO: wire it in makeViewportView()).
#pragma once

#include <epoxy/gl.h>

#include <memory>
#include <string>

#include "app/editor/view_settings.hpp"
#include "core/camera.hpp"
#include "core/formula.hpp"

namespace fraktal::editor {

struct ViewportStats {
    double renderMs = 0.0;          // GPU work of the last frame (0 when converged and idle)
    double deEvaluationsPerPixel = 0.0;
    double hitShare = 0.0;          // share of pixels whose ray hit the fractal
    double convergedShare = 0.0;    // share of pixels at the AA cap
    double reprojectedShare = 0.0;  // share of pixels whose samples were kept from earlier frames
    int samples = 0;                // samples per pixel accumulated so far
    int aaCap = 1;
    int width = 0, height = 0;      // render resolution
    int compiles = 0;               // programs built so far (a value edit must not add one)
};

class ViewportView {
public:
    virtual ~ViewportView() = default;
    // Advances the image for this state by one frame's work, on the current GL context. A
    // structure change (Formula::structureKey) recompiles; a value change only re-uploads
    // uniforms. When the compile fails, compileError() says why and the last good image stays.
    virtual void render(const Formula& formula, const Camera& camera, const ViewSettings& settings, int width,
                        int height) = 0;
    // The display-referred (sRGB, RGBA8) image, bottom row first (GL convention).
    virtual GLuint displayTexture() const = 0;
    virtual const ViewportStats& stats() const = 0;
    // Empty when the current structure compiled; else the log, naming the node (explainLog).
    virtual const std::string& compileError() const = 0;
};

std::unique_ptr<ViewportView> makeViewportView();

}  // namespace fraktal::editor
