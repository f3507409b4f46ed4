// Error of a viewport image against a reference, as the tests and `fraktal bench viewport` report
// it: PSNR of the display-referred (sRGB-encoded, clamped) RGB, the way a user sees the frame.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace fraktal::viewport {

// Both RGBA float images of the same size, scene-linear. Identical images give +infinity.
double displayPsnr(std::span<const float> image, std::span<const float> reference);

// The same display encoding as RGB8 (alpha dropped), for writing what displayPsnr compares.
std::vector<uint8_t> displayRgb8(std::span<const float> image);

}  // namespace fraktal::viewport
