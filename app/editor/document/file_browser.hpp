// What the Open / Save As file browser lists: a folder's entries (folders first), which files
// can be opened (presets, and EXRs with a fraktal preset in their header), and the recent
// places. No ImGui here: file_dialogs.cpp draws it.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace fraktal::editor {

// The first kOpenFilters are the Open dialog's choices; EnvironmentMaps lists every EXR as usable
// (the Lights tab's map), whatever its header holds.
enum class BrowserFilter { PresetsAndExrs, Presets, All, EnvironmentMaps };
inline constexpr const char* kBrowserFilterNames[] = {"Presets and fraktal EXRs (*.json, *.exr)", "Presets (*.json)",
                                                      "All files", "OpenEXR images (*.exr)"};
inline constexpr int kOpenFilters = 3;

struct BrowserEntry {
    std::string name;
    bool folder = false;
    bool usable = true;  // a folder, a preset, or an EXR with a fraktal preset in its header
    std::string note;    // why a listed file cannot be opened
};

// Folders first, then files, each by name (case-insensitive); hidden entries (a leading dot) left
// out, and files the filter rejects. An EXR without a fraktal preset is listed, marked unusable.
// A folder that cannot be read gives an empty list and `error`.
std::vector<BrowserEntry> listFolder(const std::filesystem::path& folder, BrowserFilter filter, std::string& error);

// Whether an EXR's header holds a fraktal preset (3D or 2D), the attribute `fraktal render` writes.
bool exrCarriesPreset(const std::filesystem::path& file);

// The folders of the recent files, most recent first, each once.
std::vector<std::filesystem::path> recentFolders(const std::vector<std::string>& recentFiles);

}  // namespace fraktal::editor
