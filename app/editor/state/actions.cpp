#include "app/editor/state/actions.hpp"

#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <stdexcept>

#include "app/editor/document/preset_files.hpp"
#include "app/editor/state/plane_edits.hpp"
#include "core/atomic_file.hpp"
#include "core/plane/plane_still.hpp"
#include "core/preset.hpp"
#include "core/safe_step.hpp"
#include "core/scene/scene_import.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

namespace {

void clampSelection(EditorState& s) {
    s.selectedNode = std::clamp(s.selectedNode, 0, int(s.doc.preset.formula.nodes.size()));
    if (s.doc.plane) s.planeSelection = clampedSelection(s.doc.plane->formula, s.planeSelection);
}

void adoptDocument(EditorState& s, Document d, const fs::path& path) {
    s.doc = std::move(d);
    s.history.reset(s.doc);
    s.file.path = path;
    s.file.savedFingerprint = fingerprint(s.doc);
    s.selectedNode = 0;
    s.stepFactor = AutoStepFactor::adopting(s.doc.preset.formula);
    s.slowStack = SlowStackAdvice{};
    s.planeSelection = {};
    s.fragPresets = {};
    if (s.doc.plane) s.planeHome = s.doc.plane->view;
    clampSelection(s);
}

bool isExr(const fs::path& file) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    return ext == ".exr";
}

void rememberRecent(EditorState& s, const fs::path& file) {
    pushRecent(s.file.recent, file);
    if (s.file.recentListFile.empty()) return;
    try {
        saveRecentList(s.file.recentListFile, s.file.recent);
    } catch (const std::exception&) {
        // The recent list is a convenience: failing to persist it must not fail the save.
    }
}

}  // namespace

void setStatus(EditorState& s, std::string text, bool error) {
    s.status.text = std::move(text);
    s.status.error = error;
    s.status.until = s.now + (error ? 8.0 : 4.0);
}

bool isDirty(const EditorState& s) { return fingerprint(s.doc) != s.file.savedFingerprint; }

std::string windowTitle(const EditorState& s) {
    const std::string name = s.file.path.empty() ? "untitled" : s.file.path.filename().string();
    return (isDirty(s) ? "* " : "") + name + " - fraktal";
}

void newDocument(EditorState& s) {
    Document d;
    const fs::path shipped = fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "mandelbulb.json";
    try {
        d.preset = loadPreset(shipped);
        d.preset.name = "Untitled";
    } catch (const std::exception&) {
        d.preset.formula.nodes.push_back(Node::make(*findBlock("mandelbulb")));
        d.preset.formula.nodes.push_back(Node::make(*findBlock("add_c")));
        d.preset.formula.estimator = Node::make(*findBlock("escape_log"));
    }
    adoptDocument(s, std::move(d), {});
    setStatus(s, "New document");
}

void newPlaneDocument(EditorState& s) {
    Document d;
    const fs::path shipped = fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "2d" / "mandelbrot.json";
    try {
        d.plane = loadPlanePreset(shipped);
        d.plane->name = "Untitled";
    } catch (const std::exception&) {
        d.plane.emplace();
        d.plane->formula.nodes.push_back(PlaneNode::make(*findPlaneBlock("power")));
        d.plane->formula.estimator = PlaneNode::make(*findPlaneBlock("escape"));
    }
    adoptDocument(s, std::move(d), {});
    setStatus(s, "New 2D document");
}

void resetPlaneView(EditorState& s) {
    if (s.doc.plane) s.doc.plane->view = s.planeHome;
}

std::optional<PlanePreset> planePresetFromExr(const fs::path& file) {
    const std::optional<std::string> text = readExrPlanePreset(file);
    if (!text) return std::nullopt;
    return parsePlanePreset(*text, file.string() + " [" + kExrPlanePresetAttribute + "]");
}

Preset presetFromExr(const fs::path& file) {
    Imf::InputFile in(file.c_str());
    for (auto it = in.header().begin(); it != in.header().end(); ++it) {
        const auto* text = dynamic_cast<const Imf::StringAttribute*>(&it.attribute());
        if (!text || text->value().find(kPresetFormat) == std::string::npos) continue;
        if (std::string_view(it.name()) == kExrPlanePresetAttribute) continue;  // a 2D still's
        return parsePreset(text->value(), file.string() + " [" + it.name() + "]");
    }
    throw PresetError(file.string(), "", "this EXR carries no fraktal preset in its header");
}

Document loadDocument(const fs::path& file) {
    Document d;
    if (isExr(file)) {
        std::error_code ec;
        if (!fs::is_regular_file(file, ec)) throw PresetError(file.string(), "", "no such file");
        d.plane = planePresetFromExr(file);
        if (!d.plane) d.preset = presetFromExr(file);
    } else if (isImportedSceneFile(file)) {
        d.preset = importSceneFile(file, {.lenient = true, .measure = false}).preset;
    } else if (const std::string why = notAPresetReason(file); !why.empty()) {
        throw std::runtime_error(why);  // an image or another binary file: not the JSON parser's text
    } else if (isPlanePresetFile(file)) {
        d.plane = loadPlanePreset(file);
    } else {
        d.preset = loadPreset(file);
    }
    if (!d.plane) loadEditorSection(d);
    return d;
}

// A Mandelbulber2 or Fragmentarium file opens as a new, unsaved preset (Save asks where: never
// over the .fract or .frag), and the status line lists what fraktal could not express or only
// approximates.
bool openImportedScene(EditorState& s, const fs::path& file) {
    // The step factor is measured as after any structure change: between frames, then in the
    // background (AutoStepFactor), not here before the window shows the scene.
    ImportedScene scene = importSceneFile(file, {.lenient = true, .measure = false});
    Document d;
    d.preset = std::move(scene.preset);
    adoptDocument(s, std::move(d), fs::path());
    s.stepFactor = AutoStepFactor{};
    if (!scene.presetChoices.empty()) s.fragPresets = {file, scene.presetChoices, scene.presetUsed};
    rememberRecent(s, file);
    std::string status = "Imported " + file.filename().string() + " (" + importedSceneProgram(file) + ")";
    if (!scene.unsupported.empty()) {
        status += ". Dropped, fraktal cannot express it:";
        for (const std::string& item : scene.unsupported) status += "\n  " + item;
    }
    if (!scene.approximated.empty()) {
        status += scene.unsupported.empty() ? ". Approximated:" : "\nApproximated:";
        for (const std::string& item : scene.approximated) status += "\n  " + item;
    }
    setStatus(s, status, !scene.unsupported.empty());
    return true;
}

bool applyFragPreset(EditorState& s, const std::string& name) {
    try {
        Preset next =
            importSceneFile(s.fragPresets.file, {.lenient = true, .measure = false, .fragPreset = name}).preset;
        const Formula& now = s.doc.preset.formula;
        if (stepFactorMeasured(now) && stepFactorTag(next.formula) == now.deFactorMeasuredFor) {
            next.formula.deFactor = now.deFactor;
            next.formula.deFactorMeasuredFor = now.deFactorMeasuredFor;
        }
        s.doc.preset = std::move(next);
        s.fragPresets.applied = name;
        s.history.commit(s.doc);
        setStatus(s, "Applied the preset " + name + " of " + s.fragPresets.file.filename().string());
        return true;
    } catch (const std::exception& e) {
        setStatus(s, e.what(), true);
        return false;
    }
}

bool openDocument(EditorState& s, const fs::path& file) {
    try {
        if (isImportedSceneFile(file)) return openImportedScene(s, file);
        Document d = loadDocument(file);
        const bool exr = isExr(file);
        // An EXR is an image, not a scene file: "Save" must ask where to put the preset.
        adoptDocument(s, std::move(d), exr ? fs::path() : file);
        if (!exr) rememberRecent(s, file);
        setStatus(s, "Opened " + file.string());
        return true;
    } catch (const std::exception& e) {
        setStatus(s, e.what(), true);
        return false;
    }
}

void openDropped(EditorState& s, const fs::path& file) {
    try {
        std::error_code ec;
        if (fs::is_directory(file, ec)) throw std::runtime_error("it is a folder");
        std::string ext = file.extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
        if (ext != ".json" && ext != ".exr" && ext != ".fract" && ext != ".frag")
            throw std::runtime_error(
                "it is neither a preset (.json), an EXR that fraktal wrote, a Mandelbulber2 file (.fract) nor a "
                "Fragmentarium frag (.frag)");
        loadDocument(file);  // the reason it cannot be opened, before asking about unsaved changes
    } catch (const std::exception& e) {
        setStatus(s, "Not opened: the dropped file " + file.filename().string() + ": " + e.what(), true);
        return;
    }
    requestAction(s, {PendingKind::Open, file});
}

void restoreDocument(EditorState& s, RecoveryOffer offer) {
    adoptDocument(s, std::move(offer.doc), offer.originalFile);
    s.file.savedFingerprint.clear();  // unsaved until the user saves it
    setStatus(s, "Restored the autosaved document: save it to keep it");
}

bool saveDocumentAs(EditorState& s, const fs::path& file) {
    try {
        // Atomic, with the previous version kept as FILE.bak (as core's savePresetFile).
        writeFileAtomically(file, documentFileText(s.doc), /*keepBackup=*/true);
        s.file.path = file;
        s.file.savedFingerprint = fingerprint(s.doc);
        rememberRecent(s, file);
        setStatus(s, "Saved " + file.string());
        return true;
    } catch (const std::exception& e) {
        setStatus(s, e.what(), true);
        return false;
    }
}

bool saveDocument(EditorState& s) {
    if (s.file.path.empty()) {
        s.dialogs.saveAs = true;
        return false;
    }
    return saveDocumentAs(s, s.file.path);
}

void undo(EditorState& s) {
    s.history.commit(s.doc);
    const std::string what = s.history.undoLabel();
    if (s.history.undo(s.doc)) {
        setStatus(s, "Undo " + what);
        if (!s.doc.plane) s.stepFactor.restore(s.doc.preset.formula);
    }
    clampSelection(s);
}

void redo(EditorState& s) {
    s.history.commit(s.doc);
    const std::string what = s.history.redoLabel();
    if (s.history.redo(s.doc)) {
        setStatus(s, "Redo " + what);
        if (!s.doc.plane) s.stepFactor.restore(s.doc.preset.formula);
    }
    clampSelection(s);
}

bool updateDerivedValues(EditorState& s, const std::string& structure) {
    if (s.doc.plane) return false;
    Formula& f = s.doc.preset.formula;
    if (!s.stepFactor.update(f, s.doc.preset.camera, structure)) return false;
    if (s.stepFactor.overridden || s.stepFactor.noHits) return true;  // the factor was left alone
    // An edit not committed yet (its frame) takes the factor with it when it is committed; the
    // state of a committed one, or one brought back by undo / redo, is amended in place (the
    // measurement is of `structure`: update() measured or applied for it).
    const double factor = f.deFactor;
    const std::string tag = f.deFactorMeasuredFor;
    s.history.amendPresent([&](Document& d) {
        if (d.plane || d.preset.formula.structureKey() != structure) return;
        d.preset.formula.deFactor = factor;
        d.preset.formula.deFactorMeasuredFor = tag;
    });
    return true;
}

void requestAction(EditorState& s, PendingAction action) {
    s.dialogs.pending = std::move(action);
    if (isDirty(s)) {
        s.dialogs.unsaved = true;
        return;
    }
    runPending(s);
}

void runPending(EditorState& s) {
    PendingAction a = std::move(s.dialogs.pending);
    s.dialogs.pending = {};
    switch (a.kind) {
        case PendingKind::New: newDocument(s); break;
        case PendingKind::NewPlane: newPlaneDocument(s); break;
        case PendingKind::Open: openDocument(s, a.path); break;
        case PendingKind::Quit: s.quit = true; break;
        case PendingKind::None: break;
    }
}

}  // namespace fraktal::editor
