#include "app/editor/document/file_browser.hpp"

#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <cctype>

#include "core/plane/plane_still.hpp"
#include "core/preset.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

namespace {

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

}  // namespace

bool exrCarriesPreset(const fs::path& file) {
    try {
        Imf::InputFile in(file.c_str());
        for (auto it = in.header().begin(); it != in.header().end(); ++it) {
            const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute());
            if (!text) continue;
            if (std::string_view(it.name()) == kExrPlanePresetAttribute) return true;
            if (text->value().find(kPresetFormat) != std::string::npos) return true;
        }
    } catch (const std::exception&) {
    }
    return false;
}

std::vector<BrowserEntry> listFolder(const fs::path& folder, BrowserFilter filter, std::string& error) {
    std::vector<BrowserEntry> out;
    error.clear();
    std::error_code ec;
    fs::directory_iterator it(folder, fs::directory_options::skip_permission_denied, ec);
    if (ec) {
        error = folder.string() + ": " + ec.message();
        return out;
    }
    for (; it != fs::directory_iterator(); it.increment(ec)) {
        if (ec) break;
        BrowserEntry e;
        e.name = it->path().filename().string();
        if (e.name.empty() || e.name[0] == '.') continue;
        e.folder = it->is_directory(ec);
        if (!e.folder) {
            const std::string ext = lower(it->path().extension().string());
            const bool exr = ext == ".exr";
            // A Mandelbulber2 settings file or a Fragmentarium frag opens by import
            // (core/scene/scene_import.hpp).
            const bool preset =
                ext == ".json" || (filter == BrowserFilter::PresetsAndExrs && (ext == ".fract" || ext == ".frag"));
            if (filter == BrowserFilter::Presets && !preset) continue;
            if (filter == BrowserFilter::PresetsAndExrs && !preset && !exr) continue;
            if (filter == BrowserFilter::EnvironmentMaps) {
                if (!exr) continue;
            } else if (exr && !exrCarriesPreset(it->path())) {
                e.usable = false;
                e.note = "no fraktal preset in this EXR's header";
            } else if (!preset && !exr) {
                e.usable = false;
                e.note = "neither a preset nor an EXR";
            }
        }
        out.push_back(std::move(e));
    }
    std::sort(out.begin(), out.end(), [](const BrowserEntry& a, const BrowserEntry& b) {
        if (a.folder != b.folder) return a.folder;
        return lower(a.name) < lower(b.name);
    });
    return out;
}

std::vector<fs::path> recentFolders(const std::vector<std::string>& recentFiles) {
    std::vector<fs::path> out;
    for (const std::string& f : recentFiles) {
        const fs::path folder = fs::path(f).parent_path();
        if (!folder.empty() && std::find(out.begin(), out.end(), folder) == out.end()) out.push_back(folder);
    }
    return out;
}

}  // namespace fraktal::editor
