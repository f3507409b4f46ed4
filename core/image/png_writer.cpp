#include "core/image/png_writer.hpp"

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb/stb_image_write.h>

#include <stdexcept>

#include "core/atomic_file.hpp"

namespace fraktal {

void writePngAtomic(const std::filesystem::path& path, int width, int height, std::span<const uint8_t> rgb) {
    if (rgb.size() < size_t(width) * size_t(height) * 3) throw std::logic_error("writePngAtomic: buffer too small");
    AtomicFile out(path);
    if (!stbi_write_png(out.tempPath().c_str(), width, height, 3, rgb.data(), width * 3))
        throw std::runtime_error(path.string() + ": cannot write PNG");
    out.commit();
}

}  // namespace fraktal
