// The file browser's listing (app/editor/document/file_browser.hpp): folders first, by name; the filter;
// EXRs with and without a fraktal preset in their header; recent folders.
#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>

#include <fstream>

#include "app/editor/document/file_browser.hpp"
#include "core/preset.hpp"
#include "test_support.hpp"

using namespace fraktal;
using namespace fraktal::editor;
namespace fs = std::filesystem;

namespace {

// A 1x1 one-channel EXR, with a string attribute when `attribute` is set.
void writeExr(const fs::path& file, const char* attribute, const std::string& text) {
    Imf::Header h(1, 1);
    h.channels().insert("Y", Imf::Channel(Imf::FLOAT));
    if (attribute) h.insert(attribute, Imf::StringAttribute(text));
    Imf::OutputFile out(file.c_str(), h);
    float pixel = 0.0f;
    Imf::FrameBuffer fb;
    fb.insert("Y", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&pixel), sizeof(float), sizeof(float)));
    out.setFrameBuffer(fb);
    out.writePixels(1);
}

std::vector<std::string> names(const std::vector<BrowserEntry>& entries) {
    std::vector<std::string> out;
    for (const BrowserEntry& e : entries) out.push_back(e.name + (e.folder ? "/" : "") + (e.usable ? "" : " (x)"));
    return out;
}

}  // namespace

TEST(EditorFileBrowser, FoldersFirstFilterAndExrsWithAPreset) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_browser_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "zeta");
    fs::create_directories(dir / "Alpha");
    fs::create_directories(dir / ".hidden");
    std::ofstream(dir / "b.json") << "{}";
    std::ofstream(dir / "A.JSON") << "{}";
    std::ofstream(dir / "notes.txt") << "text";
    writeExr(dir / "render.exr", "fraktal.preset", std::string("{\"format\": \"") + std::string(kPresetFormat) + "\"}");
    writeExr(dir / "photo.exr", nullptr, "");
    std::ofstream(dir / "broken.exr") << "not an exr";

    std::string error;
    EXPECT_EQ(names(listFolder(dir, BrowserFilter::PresetsAndExrs, error)),
              (std::vector<std::string>{"Alpha/", "zeta/", "A.JSON", "b.json", "broken.exr (x)", "photo.exr (x)",
                                        "render.exr"}));
    EXPECT_TRUE(error.empty());
    EXPECT_EQ(names(listFolder(dir, BrowserFilter::Presets, error)),
              (std::vector<std::string>{"Alpha/", "zeta/", "A.JSON", "b.json"}));
    EXPECT_EQ(listFolder(dir, BrowserFilter::All, error).size(), 8u);
    EXPECT_TRUE(exrCarriesPreset(dir / "render.exr"));
    EXPECT_FALSE(exrCarriesPreset(dir / "photo.exr"));

    EXPECT_TRUE(listFolder(dir / "missing", BrowserFilter::All, error).empty());
    EXPECT_NE(error.find("missing"), std::string::npos) << error;
    fs::remove_all(dir);
}

TEST(EditorFileBrowser, RecentFoldersComeFromRecentFilesOnce) {
    const std::vector<fs::path> folders = recentFolders({"/a/x.json", "/b/y.json", "/a/z.json"});
    EXPECT_EQ(folders, (std::vector<fs::path>{"/a", "/b"}));
}
