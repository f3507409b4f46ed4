// The per-pixel march state of the viewport in GPU images (layout: shaders/viewport_common.glsl),
// plus the reprojection target and the cone pre-pass image. Owned by Viewport; recreated on resize.
#pragma once

#include <epoxy/gl.h>

#include <cstdint>

namespace fraktal::viewport {

class MarchState {
   public:
    MarchState(int width, int height, int coneTile);
    ~MarchState();
    MarchState(const MarchState&) = delete;
    MarchState& operator=(const MarchState&) = delete;

    int width() const { return width_; }
    int height() const { return height_; }
    int coneTile() const { return coneTile_; }
    // Writes every image and list once, so that their memory is in place: on llvmpipe a new
    // 690x520 grid's first writes (page faults over about 90 MB) took 60 ms of the frame that made
    // them. A grid made ahead on another context (the editor's worker) pays them there.
    void touchAll() const;
    // The view the rays were last started for (viewport_common.glsl, GENERATION_SHIFT): a pixel
    // whose rayInfo and centre hold another is of an older view, not started yet. 0: none (a new
    // state's rays, cleared to 0).
    int generation = 0;
    // Binds the shade list at SSBO binding 2 and the march list at 3. The images are bound by
    // each pass, at the units its program gave them (pass_images.hpp).
    void bindLists() const;
    // Empties the shade list (ShadeList in shaders/viewport_common.glsl): no pixels, no groups.
    void clearShadeList() const;
    // Empties the march list (MarchList in shaders/viewport_common.glsl) the same way.
    void clearMarchList() const;
    // The entries on the march list (waits for the passes that append).
    uint32_t marchListCount() const;

    GLuint rayState = 0, rayInfo = 0, sampleColor = 0, accum = 0, image = 0, centre = 0, cone = 0;
    // xyz: the world point whose shading the pixel's sample-0 colour is (a carried colour keeps
    // its own point); w: 1 when there is one (a surface colour), 0 for background.
    GLuint colourPoint = 0;
    // The image shown and read back: `image` at rest, a reconstruction from the scattered samples
    // under motion (shaders/viewport_resolve.comp). Reprojection carries `image`, never this.
    GLuint shown = 0;
    // Under motion, where each pixel's one sample lies (xy, pixels), its depth (z) and whether it
    // has one (w): written by the accumulate pass for the resolve pass's reconstruction.
    GLuint samplePosition = 0;
    // Reprojection target (written by reproject_pass): the nearest distance keys (r32ui,
    // width x 3 height: rows of the start points, then of the carried colours in the pixel, then
    // of those near it; a key is the distance's float bits, all ones for none; an image rather
    // than a buffer because llvmpipe loads a buffer lane by lane: the starts' 9 reads per pixel
    // cost 7-8 ms more of the march pass at 640x360), carried colours (rgba32f; a: carry
    // age + 1, 0: none) and each carried colour's point (rgba32f; xyz, and w: its distance from
    // the new camera). The colour images are twice as tall: row y holds the colour whose point
    // lies in pixel row y, row height + y the one near it, which a pixel takes when no point lies
    // in it (shaders/viewport_reproject.comp).
    GLuint reprojDepth = 0, reprojColor = 0, reprojCarried = 0;
    // The pixels to shade this frame: 4 uints of indirect-dispatch header and count, then one
    // pixel index per entry (room for every pixel).
    GLuint shadeList = 0;
    // The rays left marching after the full-screen march pass's first steps, with the steps they
    // have left (shaders/viewport_march.comp): the same header, then two uints per entry.
    GLuint marchList = 0;

   private:
    int width_, height_, coneTile_;
};

}  // namespace fraktal::viewport
