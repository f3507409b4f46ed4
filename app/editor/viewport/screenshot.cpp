#include "app/editor/viewport/screenshot.hpp"

#include <epoxy/gl.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/editor/document/preset_files.hpp"

namespace fraktal::editor {

namespace {
void appendBytes(void* context, void* data, int size) {
    auto* out = static_cast<std::string*>(context);
    out->append(static_cast<const char*>(data), size_t(size));
}
}  // namespace

void saveWindowScreenshot(const std::filesystem::path& path, int width, int height) {
    std::vector<unsigned char> pixels(size_t(width) * size_t(height) * 3);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
    // GL rows are bottom first; PNG rows top first. (Flipped here rather than through stb's
    // global flip flag, which other writers in the process share.)
    const size_t row = size_t(width) * 3;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(pixels.begin() + long(y * row), pixels.begin() + long((y + 1) * row),
                         pixels.begin() + long((height - 1 - y) * row));
    std::string png;
    if (!stbi_write_png_to_func(appendBytes, &png, width, height, 3, pixels.data(), int(row)))
        throw std::runtime_error(path.string() + ": cannot encode the screenshot as PNG");
    writeFileAtomically(path, png, /*keepBackup=*/false);
}

}  // namespace fraktal::editor
