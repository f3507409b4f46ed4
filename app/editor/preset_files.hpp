// Saving presets safely and remembering recent files.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/preset.hpp"

namespace fraktal::editor {

// Writes `text` to `path` atomically: a temp file in the same folder, flushed, then renamed
// over the target, so a crash never leaves a half-written file. An existing file is first
// copied to "<path>.bak". Throws std::runtime_error naming the file and the reason.
void writeFileAtomically(const std::filesystem::path& path, const std::string& text, bool keepBackup = true);

void savePresetFile(const std::filesystem::path& path, const Preset& preset);

// Most recent first, no duplicates (compared as absolute, normalised paths), at most `limit`.
void pushRecent(std::vector<std::string>& recent, const std::filesystem::path& file, size_t limit = 10);

// The editor's own folder for its ini, recent list and user presets: $XDG_CONFIG_HOME/fraktal
// or ~/.config/fraktal (created on demand); the current folder if neither is known.
std::filesystem::path configFolder();
std::filesystem::path userPresetFolder();  // configFolder()/presets

std::vector<std::string> loadRecentList(const std::filesystem::path& file);
void saveRecentList(const std::filesystem::path& file, const std::vector<std::string>& recent);

}  // namespace fraktal::editor
