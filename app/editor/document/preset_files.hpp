// Remembering recent files, and where the editor keeps its own files. (Presets are saved with
// core's fraktal::savePresetFile, other files with fraktal::writeFileAtomically.)
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/preset.hpp"

namespace fraktal::editor {

// Most recent first, no duplicates (compared as absolute, normalised paths), at most `limit`.
void pushRecent(std::vector<std::string>& recent, const std::filesystem::path& file, size_t limit = 10);

// The editor's own folder for its ini, recent list and user presets: $XDG_CONFIG_HOME/fraktal
// or ~/.config/fraktal (created on demand); the current folder if neither is known.
std::filesystem::path configFolder();
std::filesystem::path userPresetFolder();  // configFolder()/presets

// Why `file` cannot be a preset, whatever its name says, from its first bytes: an image (PNG,
// JPEG, GIF, TIFF, BMP, WebP, Radiance HDR) or another binary file (a NUL byte, or bytes that are
// not UTF-8 text). One sentence that names the file, e.g. "x.png is an image, not a fraktal
// preset: ..."; empty when it may be one (the preset reader then says what is wrong with it).
std::string notAPresetReason(const std::filesystem::path& file);

std::vector<std::string> loadRecentList(const std::filesystem::path& file);
void saveRecentList(const std::filesystem::path& file, const std::vector<std::string>& recent);

}  // namespace fraktal::editor
