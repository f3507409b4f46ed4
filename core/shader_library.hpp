// The GLSL templates in shaders/, embedded into the binary at build time.
#pragma once

#include <string_view>

namespace fraktal {

// The text of shaders/<name>; throws std::runtime_error naming the file if it is unknown.
std::string_view shaderTemplate(std::string_view name);

}  // namespace fraktal
