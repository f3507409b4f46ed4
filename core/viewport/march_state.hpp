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
    // Binds every state image at its unit (0..6, as the shaders declare them) and the shade list
    // at SSBO binding 2.
    void bindImages() const;
    // Empties the shade list (ShadeList in shaders/viewport_common.glsl): no pixels, no groups.
    void clearShadeList() const;

    GLuint rayState = 0, rayInfo = 0, sampleColor = 0, accum = 0, image = 0, centre = 0, cone = 0;
    // Reprojection target (written by reproject_pass as images 7 and 8): distances, carried colours.
    GLuint reprojDistance = 0, reprojColor = 0;
    // The pixels to shade this frame: 4 uints of indirect-dispatch header and count, then one
    // pixel index per entry (room for every pixel).
    GLuint shadeList = 0;

   private:
    int width_, height_;
};

}  // namespace fraktal::viewport
