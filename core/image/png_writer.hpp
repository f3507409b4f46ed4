// 8-bit RGB PNG output (stb_image_write), atomically: temp file in the same folder, then rename.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>

namespace fraktal {

// Writes `rgb` (width * height * 3 bytes, rows from the top) to `path` atomically; throws naming
// the file on failure (nothing is left behind).
void writePngAtomic(const std::filesystem::path& path, int width, int height, std::span<const uint8_t> rgb);

}  // namespace fraktal
