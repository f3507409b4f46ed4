#include "core/import/fract_file.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <sstream>

#include "core/json_reader.hpp"

namespace fraktal::mb2 {

namespace {

struct Mb2Default {
    std::string_view key, value;
};
#include "core/import/mb2_defaults.inc"

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::string where(int line) { return "line " + std::to_string(line); }

}  // namespace

const FractEntry* FractFile::find(const std::string& section, const std::string& key) const {
    const auto s = sections.find(section);
    if (s == sections.end()) return nullptr;
    const auto e = s->second.find(key);
    return e == s->second.end() ? nullptr : &e->second;
}

FractFile parseFractFile(std::string_view text, const std::string& source) {
    FractFile file;
    file.source = source;
    std::istringstream in{std::string(text)};
    std::string rawLine;
    int lineNumber = 0;
    std::string section;
    bool header = false;
    while (std::getline(in, rawLine)) {
        ++lineNumber;
        const std::string_view line = trim(rawLine);
        if (lineNumber == 1 && line.starts_with("Mandelbulber 1"))
            throw PresetError(source, where(1),
                              "a Mandelbulber 1.x settings file (v1.21 format), which is not read: open it in "
                              "Mandelbulber2 and save it there to convert it to the v2 format");
        if (line.starts_with("#")) {
            if (line.starts_with("# Mandelbulber settings file")) header = true;
            if (line.starts_with("# version")) {
                file.version = std::string(trim(line.substr(9)));
                file.versionNumber = parseNumber(file.version).value_or(0.0);
            }
            continue;
        }
        if (line.empty() && section != "description") continue;
        if (!header)
            throw PresetError(source, where(lineNumber),
                              "not a Mandelbulber2 settings file (the first line must be \"# Mandelbulber settings "
                              "file\")");
        if (line.starts_with("[") && line.ends_with("]")) {
            section = std::string(line.substr(1, line.size() - 2));
            if (section == "frames" || section == "keyframes") file.animationRows[section] = -1;  // the header row
            continue;
        }
        if (section == "description") {
            file.description += (file.description.empty() ? "" : "\n") + std::string(line);
            continue;
        }
        if (file.animationRows.count(section)) {
            if (!line.empty()) ++file.animationRows[section];
            continue;
        }
        if (section.empty()) throw PresetError(source, where(lineNumber), "a parameter before the first [section]");
        const size_t space = line.find(' ');
        const size_t semicolon = line.find(';');
        if (space == std::string_view::npos || semicolon == std::string_view::npos || semicolon < space)
            throw PresetError(source, "[" + section + "] " + where(lineNumber),
                              "expected `name value;`, found \"" + std::string(line.substr(0, 80)) + "\"");
        const std::string key(line.substr(0, space));
        FractEntry entry{std::string(trim(line.substr(space + 1, semicolon - space - 1))), lineNumber};
        auto& entries = file.sections[section];
        if (entries.count(key))
            throw PresetError(source, "[" + section + "] " + key + " (" + where(lineNumber) + ")",
                              "given twice (first on " + where(entries[key].line) + ")");
        entries.emplace(key, std::move(entry));
    }
    if (!header)
        throw PresetError(
            source, where(1),
            "not a Mandelbulber2 settings file (the first line must be \"# Mandelbulber settings file\")");
    return file;
}

FractFile loadFractFile(const std::filesystem::path& path) {
    return parseFractFile(readGuardedFile(path), path.string());
}

bool isFractPath(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext == ".fract";
}

std::optional<double> parseNumber(std::string_view text) {
    std::string s(trim(text));
    std::replace(s.begin(), s.end(), ',', '.');  // the saving locale's decimal separator
    if (s.empty()) return std::nullopt;
    double v = 0.0;
    const char* begin = s.data() + (s.front() == '+' ? 1 : 0);
    const auto [end, ec] = std::from_chars(begin, s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
    return v;
}

namespace {
std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    text = trim(text);
    while (!text.empty()) {
        const size_t space = text.find_first_of(" \t");
        out.push_back(text.substr(0, space));
        if (space == std::string_view::npos) break;
        text = trim(text.substr(space));
    }
    return out;
}
}  // namespace

std::optional<vec3> parseVector(std::string_view text) {
    const auto parts = words(text);
    if (parts.size() != 3) return std::nullopt;
    vec3 v;
    for (int i = 0; i < 3; ++i) {
        const auto x = parseNumber(parts[size_t(i)]);
        if (!x) return std::nullopt;
        v[i] = *x;
    }
    return v;
}

std::optional<glm::dvec4> parseVector4(std::string_view text) {
    const auto parts = words(text);
    if (parts.size() != 4) return std::nullopt;
    glm::dvec4 v;
    for (int i = 0; i < 4; ++i) {
        const auto x = parseNumber(parts[size_t(i)]);
        if (!x) return std::nullopt;
        v[i] = *x;
    }
    return v;
}

std::optional<bool> parseBoolean(std::string_view text) {
    text = trim(text);
    if (text == "true" || text == "1") return true;
    if (text == "false" || text == "0") return false;
    return std::nullopt;
}

std::optional<vec3> parseColour(std::string_view text) {
    const auto parts = words(text);
    if (parts.size() != 3) return std::nullopt;
    vec3 c;
    for (int i = 0; i < 3; ++i) {
        unsigned value = 0;
        const auto p = parts[size_t(i)];
        const auto [end, ec] = std::from_chars(p.data(), p.data() + p.size(), value, 16);
        if (ec != std::errc() || end != p.data() + p.size() || value > 0xffff) return std::nullopt;
        c[i] = double(value) / 65535.0;
    }
    return c;
}

const char* defaultValue(std::string_view key, bool main) {
    const auto& table =
        main ? std::span<const Mb2Default>(kMainDefaults) : std::span<const Mb2Default>(kFractalDefaults);
    for (const Mb2Default& d : table)
        if (d.key == key) return d.value.data();
    return nullptr;
}

}  // namespace fraktal::mb2
