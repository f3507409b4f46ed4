// What `fraktal render` and the jobs `fraktal farm` writes share: the --size option's syntax.
#pragma once

#include <string>

#include "core/render_settings.hpp"

namespace fraktal::cli {

// "WIDTHxHEIGHT" into r.width, r.height; throws naming --size and the accepted range.
void parseSize(const std::string& text, RenderSettings& r);

}  // namespace fraktal::cli
