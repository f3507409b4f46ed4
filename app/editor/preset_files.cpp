#include "app/editor/preset_files.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>
#include <unistd.h>

namespace fraktal::editor {

namespace fs = std::filesystem;

void writeFileAtomically(const fs::path& path, const std::string& text, bool keepBackup) {
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    std::string tempName = ".";
    tempName += path.filename().string();
    tempName += ".tmp" + std::to_string(::getpid());
    const fs::path temp = folder / tempName;
    {
        FILE* out = std::fopen(temp.c_str(), "wb");
        if (!out) throw std::runtime_error(path.string() + ": cannot write: " + std::strerror(errno));
        const bool ok = std::fwrite(text.data(), 1, text.size(), out) == text.size() && std::fflush(out) == 0 &&
                        ::fsync(::fileno(out)) == 0;
        const int err = errno;
        std::fclose(out);
        if (!ok) {
            fs::remove(temp);
            throw std::runtime_error(path.string() + ": cannot write: " + std::strerror(err));
        }
    }
    std::error_code ec;
    if (keepBackup && fs::exists(path)) {
        fs::copy_file(path, fs::path(path.string() + ".bak"), fs::copy_options::overwrite_existing, ec);
        if (ec) {
            fs::remove(temp);
            throw std::runtime_error(path.string() + ".bak: cannot keep a backup: " + ec.message());
        }
    }
    fs::rename(temp, path, ec);
    if (ec) {
        fs::remove(temp);
        throw std::runtime_error(path.string() + ": cannot replace: " + ec.message());
    }
}

void savePresetFile(const fs::path& path, const Preset& preset) {
    writeFileAtomically(path, presetToJson(preset).dump(2) + "\n");
}

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
