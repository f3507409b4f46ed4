#include "cli/render_options.hpp"

#include <regex>
#include <stdexcept>

namespace fraktal::cli {

void parseSize(const std::string& text, RenderSettings& r) {
    std::smatch m;
    static_assert(kMaxImageSide < 1000000);
    if (!std::regex_match(text, m, std::regex(R"((-?\d{1,9})[xX](-?\d{1,9}))")))
        throw std::runtime_error("--size '" + text + "': expected WIDTHxHEIGHT, e.g. 1920x1080");
    const long long w = std::stoll(m[1]), h = std::stoll(m[2]);
    if (w < 1 || h < 1 || w > kMaxImageSide || h > kMaxImageSide)
        throw std::runtime_error("--size '" + text + "': each side must be within 1.." + std::to_string(kMaxImageSide));
    r.width = int(w);
    r.height = int(h);
}

}  // namespace fraktal::cli
