// A PNG of the window's back buffer (what the user sees), written atomically.
#pragma once

#include <filesystem>

namespace fraktal::editor {

// Reads the current framebuffer (0) of size w x h and writes it to `path`. Throws naming the
// file on failure.
void saveWindowScreenshot(const std::filesystem::path& path, int width, int height);

}  // namespace fraktal::editor
