#include "core/viewport/converge.hpp"

namespace fraktal::viewport {

Converged renderUntilSettled(Viewport& viewport, const Formula& formula, const Camera& camera,
                             const RenderSettings& render, const ShadingSettings& shading, int width, int height,
                             int maxFrames, const ThinLens& lens) {
    Converged out;
    for (out.frames = 0; out.frames < maxFrames && !viewport.settled(); ++out.frames)
        viewport.render(formula, camera, render, shading, width, height, lens);
    out.settled = viewport.settled();
    out.image = viewport.readImage();
    return out;
}

}  // namespace fraktal::viewport
