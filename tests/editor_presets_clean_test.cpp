// Every shipped preset (3D in presets/*.json, 2D in presets/2d/*.json) opens in the editor as it
// was saved: after opening it as the editor does and running a frame without input (the camera's
// orbit and fly rules, the 2D view's navigation, the derived values), its fingerprint is the one
// taken when it opened, so the title has no unsaved mark; and every number of the file is written
// back exactly (the file text the editor saves holds the same double at the same place, and
// reopening that text gives the same document).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/editor/document/document.hpp"
#include "app/editor/input/camera_controller.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/state/plane_edits.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::vector<fs::path> shippedPresets() {
    std::vector<fs::path> files;
    for (const char* folder : {"presets", "presets/2d"})
        for (const auto& e : fs::directory_iterator(fs::path(FRAKTAL_SOURCE_DIR) / folder))
            if (e.path().extension() == ".json") files.push_back(e.path());
    std::sort(files.begin(), files.end());
    return files;
}

json readJson(const fs::path& file) {
    std::ifstream in(file);
    return json::parse(in);
}

// Every number of `j` by its JSON pointer.
void numbersOf(const json& j, const std::string& at, std::map<std::string, double>& out) {
    if (j.is_number()) {
        out[at] = j.get<double>();
    } else if (j.is_object()) {
        for (const auto& [k, v] : j.items()) numbersOf(v, at + "/" + k, out);
    } else if (j.is_array()) {
        for (size_t i = 0; i < j.size(); ++i) numbersOf(j[i], at + "/" + std::to_string(i), out);
    }
}

// Where a fingerprint looks from: the 3D camera or the 2D view (what a frame's input moves).
std::string viewOf(const std::string& fingerprint) {
    const json j = json::parse(fingerprint);
    return j.value("camera", j.value("view", json())).dump();
}

// One frame without input, as the editor's loop runs it over a document that was just opened.
void frameWithoutInput(EditorState& s, CameraMode mode) {
    if (s.doc.plane) {
        s.doc.plane->view = navigatePlane(s.doc.plane->view, PlaneInput{}, 690, 584, 920.0);
        return;
    }
    CameraControls controls;
    controls.mode = mode;
    CameraInput in;
    in.viewportHeight = 779.0;
    in.dt = 1.0 / 60.0;
    Camera& cam = s.doc.preset.camera;
    if (mode == CameraMode::Orbit) {
        EXPECT_FALSE(orbitCamera(cam, in, controls));
    } else {
        const Formula& f = s.doc.preset.formula;
        EXPECT_FALSE(flyCamera(cam, f, in, controls, [](const vec3&) { return 1.0; }));
        EXPECT_FALSE(orbitCamera(cam, in, controls));
    }
    updateDerivedValues(s);
}

TEST(EditorPresetsClean, EveryShippedPresetOpensUnchanged) {
    const std::vector<fs::path> files = shippedPresets();
    ASSERT_GE(files.size(), 39u);  // 34 in presets, 5 in presets/2d
    for (const fs::path& file : files) {
        SCOPED_TRACE(file.string());
        EditorState s;
        ASSERT_TRUE(openDocument(s, file)) << s.status.text;
        EXPECT_EQ(fingerprint(s.doc), s.file.savedFingerprint);
        for (const CameraMode mode : {CameraMode::Orbit, CameraMode::Fly, CameraMode::Orbit})
            for (int frame = 0; frame < 3; ++frame) frameWithoutInput(s, mode);
        EXPECT_FALSE(isDirty(s)) << "the document changed without input:\n  opened " << viewOf(s.file.savedFingerprint)
                                 << "\n  now    " << viewOf(fingerprint(s.doc));
        EXPECT_EQ(windowTitle(s), file.filename().string() + " - fraktal");
    }
}

TEST(EditorPresetsClean, EveryNumberOfEveryShippedPresetRoundTripsExactly) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_presets_clean_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    for (const fs::path& file : shippedPresets()) {
        SCOPED_TRACE(file.string());
        const Document d = loadDocument(file);
        const std::string text = documentFileText(d);
        std::map<std::string, double> original, saved;
        numbersOf(readJson(file), "", original);
        numbersOf(json::parse(text), "", saved);
        int compared = 0;
        for (const auto& [at, value] : original) {
            const auto written = saved.find(at);
            if (written == saved.end()) continue;  // a default the writer leaves out, or a migrated field
            ++compared;
            EXPECT_EQ(written->second, value)
                << at << ": the file says " << json(value).dump() << ", saved as " << json(written->second).dump();
        }
        EXPECT_GT(compared, 0);
        // The saved text opens as the same document, and saves as the same text.
        const fs::path copy = dir / file.filename();
        std::ofstream(copy) << text;
        const Document reopened = loadDocument(copy);
        EXPECT_EQ(fingerprint(reopened), fingerprint(d));
        EXPECT_EQ(documentFileText(reopened), text);
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fraktal::editor
