// The per-pixel march state of the viewport in GPU images (layout: shaders/viewport_common.glsl),
// plus the reprojection target and the cone pre-pass image. Owned by Viewport; recreated on resize.
#pragma once

#include <epoxy/gl.h>

namespace fraktal::viewport {

class MarchState {
   public:
    MarchState(int width, int height, int coneTile);
    ~MarchState();
    MarchState(const MarchState&) = delete;
    MarchState& operator=(const MarchState&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    // Binds every state image at its unit (0..6, as the shaders declare them).
    void bindImages() const;

    GLuint rayState = 0, rayInfo = 0, sampleColor = 0, accum = 0, image = 0, centre = 0, cone = 0;
    // Reprojection target: distances, carried colours, depth.
    GLuint reprojDistance = 0, reprojColor = 0, reprojDepth = 0, reprojFramebuffer = 0;

   private:
    int width_, height_;
};

}  // namespace fraktal::viewport
