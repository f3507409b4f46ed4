// The CPU reference renderer: the core's double-precision DE (fraktal::evaluate) with the same
// marcher and shading as shaders/march.glsl and shaders/shade.glsl, one sample per pixel at the
// pixel centre. Slow; for golden tests at small sizes, and as the definition of what the GL
// still renderer must produce.
#pragma once

#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/image/image_strip.hpp"
#include "core/shading_params.hpp"

namespace fraktal {

// The whole image as one strip (rows from the top). `render` gives the size, maxSteps and
// transparentBackground; `threads` 0 uses all cores.
ImageStrip renderReference(const Formula& formula, const Camera& camera, const RenderSettings& render,
                           const ShadingParams& shading, int threads = 0);

}  // namespace fraktal
