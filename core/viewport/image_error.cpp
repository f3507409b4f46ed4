#include "core/viewport/image_error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace fraktal::viewport {

namespace {

double srgbEncode(double c) {  // IEC 61966-2-1, as shaders/viewport_display.frag
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
}

}  // namespace

double displayPsnr(std::span<const float> image, std::span<const float> reference) {
    if (image.size() != reference.size() || image.size() % 4 != 0)
        throw std::invalid_argument("displayPsnr: images differ in size");
    double squared = 0.0;
    size_t count = 0;
    for (size_t i = 0; i < image.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) {
            const double e = srgbEncode(image[i + c]) - srgbEncode(reference[i + c]);
            squared += e * e;
            ++count;
        }
    if (count == 0 || squared == 0.0) return std::numeric_limits<double>::infinity();
    return 10.0 * std::log10(1.0 / (squared / double(count)));
}

std::vector<uint8_t> displayRgb8(std::span<const float> image) {
    std::vector<uint8_t> rgb;
    rgb.reserve(image.size() / 4 * 3);
    for (size_t i = 0; i + 3 < image.size(); i += 4)
        for (size_t c = 0; c < 3; ++c) rgb.push_back(uint8_t(std::lround(srgbEncode(image[i + c]) * 255.0)));
    return rgb;
}

}  // namespace fraktal::viewport
