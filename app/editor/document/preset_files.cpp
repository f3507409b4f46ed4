#include "app/editor/document/preset_files.hpp"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

namespace fraktal::editor {

namespace fs = std::filesystem;

void pushRecent(std::vector<std::string>& recent, const fs::path& file, size_t limit) {
    std::error_code ec;
    fs::path abs = fs::weakly_canonical(fs::absolute(file), ec);
    if (ec) abs = fs::absolute(file).lexically_normal();
    const std::string key = abs.string();
    std::erase(recent, key);
    recent.insert(recent.begin(), key);
    if (recent.size() > limit) recent.resize(limit);
}

fs::path configFolder() {
    if (const char* xdg = std::getenv("XDG_CONFIG_HOME"); xdg && *xdg) return fs::path(xdg) / "fraktal";
    if (const char* home = std::getenv("HOME"); home && *home) return fs::path(home) / ".config" / "fraktal";
    return fs::path(".");
}

fs::path userPresetFolder() { return configFolder() / "presets"; }

std::vector<std::string> loadRecentList(const fs::path& file) {
    std::ifstream in(file);
    if (!in) return {};
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    std::vector<std::string> out;
    if (!j.is_array()) return out;
    for (const auto& e : j)
        if (e.is_string()) out.push_back(e.get<std::string>());
    return out;
}

void saveRecentList(const fs::path& file, const std::vector<std::string>& recent) {
    std::error_code ec;
    fs::create_directories(file.parent_path(), ec);
    writeFileAtomically(file, nlohmann::json(recent).dump(2) + "\n", /*keepBackup=*/false);
}

}  // namespace fraktal::editor
