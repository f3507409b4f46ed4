// What part of the plane an image shows, and where each pixel's samples fall. Pure logic shared
// by the GL renderer (shaders/plane_render.comp computes the same positions), the CPU reference
// and the editor's pan/zoom.
#pragma once

#include <cmath>

#include "core/plane/plane_block.hpp"

namespace fraktal {

struct PlaneViewRect {
    real2 center{-0.5, 0.0};
    double width = 3.0;  // of the image, in plane units; the height follows the image's aspect

    double pixelSize(int imageWidth) const { return width / double(imageWidth); }
};

// Sample k's offset inside its pixel in [0, 1)^2: the R2 low-discrepancy sequence (Martin
// Roberts 2018), in float exactly as the shader computes it; sample 0 is the pixel centre.
inline glm::vec2 planeSampleOffset(int k) {
    const glm::vec2 v = glm::vec2(0.5f) + float(k) * glm::vec2(0.7548776662466927f, 0.5698402909980532f);
    return v - glm::floor(v);
}

// The plane position of a point of pixel (x, y), counted from the top left, at offset o in the
// pixel; y grows upward in the plane.
inline real2 planePixelPosition(const PlaneViewRect& v, int imageWidth, int imageHeight, int x, int y, glm::vec2 o) {
    return v.center + real2(real(x) + real(o.x) - real(0.5) * real(imageWidth),
                            real(0.5) * real(imageHeight) - real(y) - real(o.y)) *
                          v.pixelSize(imageWidth);
}

// Pan by a drag of (dx, dy) pixels (the plane follows the cursor).
inline PlaneViewRect planePanned(PlaneViewRect v, int imageWidth, double dxPixels, double dyPixels) {
    v.center -= real2(dxPixels, -dyPixels) * v.pixelSize(imageWidth);
    return v;
}

// Zoom by `factor` (> 1: in) keeping the plane point under the cursor (pixel coordinates from
// the top left, fractional allowed) where it is.
inline PlaneViewRect planeZoomedAt(PlaneViewRect v, int imageWidth, int imageHeight, double cursorX, double cursorY,
                                   double factor) {
    const real2 offset = real2(cursorX - 0.5 * imageWidth, 0.5 * imageHeight - cursorY) * v.pixelSize(imageWidth);
    const real2 under = v.center + offset;
    v.width /= factor;
    v.center = under - offset / factor;
    return v;
}

}  // namespace fraktal
