#include "app/editor/document/preset_files.hpp"

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string_view>

namespace fraktal::editor {

namespace fs = std::filesystem;
using namespace std::string_view_literals;

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

namespace {

// The image formats a person may pick by mistake, by their signatures.
const char* imageFormat(std::string_view head) {
    static constexpr struct {
        std::string_view magic;
        const char* name;
    } kImages[] = {{"\x89PNG\r\n\x1a\n"sv, "PNG"},
                   {"\xff\xd8\xff"sv, "JPEG"},
                   {"GIF87a"sv, "GIF"},
                   {"GIF89a"sv, "GIF"},
                   {"II*\0"sv, "TIFF"},
                   {"MM\0*"sv, "TIFF"},
                   {"BM"sv, "BMP"},
                   {"#?RADIANCE"sv, "Radiance HDR"},
                   {"#?RGBE"sv, "Radiance HDR"}};
    for (const auto& image : kImages)
        if (head.starts_with(image.magic)) return image.name;
    if (head.size() >= 12 && head.starts_with("RIFF") && head.substr(8, 4) == "WEBP") return "WebP";
    return nullptr;
}

// Whether `text` is UTF-8 without NUL bytes; a sequence cut off at its end (the file read only
// in part) is not held against it.
bool looksLikeText(std::string_view text) {
    size_t i = 0;
    while (i < text.size()) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c == 0) return false;
        const size_t length = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
        if (length == 0) return false;
        for (size_t k = 1; k < length; ++k) {
            if (i + k >= text.size()) return true;
            if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return false;
        }
        i += length;
    }
    return true;
}

}  // namespace

std::string notAPresetReason(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return "";  // the reader says why it cannot be read
    std::string head(4096, '\0');
    in.read(head.data(), std::streamsize(head.size()));
    head.resize(size_t(in.gcount()));
    constexpr const char* kWhatOpens =
        ": open a preset (.json), an EXR that fraktal rendered, or a Mandelbulber2 file (.fract)";
    const std::string name = file.filename().string();
    if (const char* format = imageFormat(head))
        return name + " is an image, not a fraktal preset (a " + format + " file)" + kWhatOpens;
    if (!looksLikeText(head)) return name + " is a binary file, not a fraktal preset (JSON text)" + kWhatOpens;
    return "";
}

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
