// The editor's 2D documents, without a window: undo/redo of a scripted sequence of 2D
// edits restores every state exactly; pan and zoom keep the plane point under the cursor where
// it is; 2D presets and 2D stills open as 2D documents, save atomically and autosave; compile
// errors name the 2D node.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "app/editor/document/autosave.hpp"
#include "app/editor/document/node_list_edits.hpp"
#include "app/editor/document/undo_history.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/state/plane_edits.hpp"
#include "core/plane/plane_glsl.hpp"
#include "core/plane/plane_still.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

fs::path planePresetPath(const char* name) { return test::sourceDir() / "presets" / "2d" / name; }

Document planeDocument(const char* name) {
    Document d;
    d.plane = loadPlanePreset(planePresetPath(name));
    return d;
}

// A folder of its own, removed at the end.
struct TempDir {
    fs::path dir;
    explicit TempDir(const std::string& tag)
        : dir(fs::temp_directory_path() / ("fraktal_" + tag + "_" + std::to_string(::getpid()))) {
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    ~TempDir() { fs::remove_all(dir); }
};

// Every kind of edit the 2D panels and the view make.
std::vector<std::function<void(Document&)>> scriptedPlaneEdits() {
    const PlaneSelection loop0{PlaneList::Loop, 0};
    return {
        [=](Document& d) { setPlaneParam(d.plane->formula, loop0, 0, 3.0); },  // power 2 -> 3
        [](Document& d) { d.plane->formula.iterations = 77; },
        [](Document& d) { d.plane->formula.bailout = 1.0 / 3.0; },
        [](Document& d) {
            addPlaneBlock(d.plane->formula, *findPlaneBlock("rotate"), {PlaneList::Start, 0});
        },
        [](Document& d) { duplicateNodeAt(d.plane->formula.start, 0); },
        [=](Document& d) { addPlaneBlock(d.plane->formula, *findPlaneBlock("abs_fold"), loop0); },
        [](Document& d) { moveNodeWithin(d.plane->formula.nodes, 0, 1); },
        [](Document& d) { d.plane->formula.nodes[0].enabled = false; },
        [](Document& d) { d.plane->formula.nodes[1].period = 2; },
        [](Document& d) { removeNodeAt(d.plane->formula.start, 1); },
        [=](Document& d) { addPlaneBlock(d.plane->formula, *findPlaneBlock("triangle"), loop0); },
        [](Document& d) { d.plane->colouring.paletteD = vec3(0.0, 1.0 / 3.0, 2.0 / 3.0); },
        [](Document& d) { d.plane->colouring.edgeWidth = 0.0; },
        [](Document& d) { d.plane->render.exposure = -0.5; },
        [](Document& d) { d.plane->render.view = "ACES"; },
        [](Document& d) { d.plane->name = "edited"; },
    };
}

TEST(EditorPlaneUndo, ScriptedSequenceUndoesAndRedoesToEveryStateExactly) {
    Document doc = planeDocument("mandelbrot.json");
    UndoHistory history;
    history.reset(doc);
    std::vector<Document> states{doc};
    for (const auto& edit : scriptedPlaneEdits()) {
        edit(doc);
        ASSERT_TRUE(history.commit(doc)) << "each scripted edit changes the document (edit " << states.size() << ")";
        states.push_back(doc);
    }
    for (size_t i = 1; i < states.size(); ++i) ASSERT_NE(fingerprint(states[i]), fingerprint(states[i - 1]));

    // Exactly: the whole preset's JSON, and the doubles of the view (the deepest state).
    auto expectSame = [](const Document& a, const Document& b, const std::string& what) {
        ASSERT_TRUE(a.plane && b.plane) << what;
        EXPECT_EQ(planePresetToJson(*a.plane), planePresetToJson(*b.plane)) << what;
        EXPECT_EQ(a.plane->view.center, b.plane->view.center) << what;
        EXPECT_EQ(a.plane->view.width, b.plane->view.width) << what;
        EXPECT_EQ(a.plane->formula.structureKey(), b.plane->formula.structureKey()) << what;
    };
    for (size_t i = states.size() - 1; i-- > 0;) {
        ASSERT_TRUE(history.undo(doc));
        expectSame(doc, states[i], "after undo back to state " + std::to_string(i));
    }
    EXPECT_FALSE(history.undo(doc));
    expectSame(doc, planeDocument("mandelbrot.json"), "back at the file");
    for (size_t i = 1; i < states.size(); ++i) {
        ASSERT_TRUE(history.redo(doc));
        expectSame(doc, states[i], "after redo to state " + std::to_string(i));
    }
    EXPECT_FALSE(history.redo(doc));
    EXPECT_EQ(doc.plane->formula.bailout, 1.0 / 3.0);
}

TEST(EditorPlaneUndo, PanAndZoomRecordNoStepAndUndoKeepsTheView) {
    Document doc = planeDocument("mandelbrot.json");
    UndoHistory history;
    history.reset(doc);
    doc.plane->formula.iterations = 77;
    ASSERT_TRUE(history.commit(doc));
    PlaneInput in;
    in.dragX = 13.0;
    in.wheel = 3.0;
    doc.plane->view = navigatePlane(doc.plane->view, in, 640, 480, 640.0);
    const PlaneViewRect moved = doc.plane->view;
    EXPECT_FALSE(history.commit(doc)) << "panning and zooming are not edits";
    EXPECT_EQ(history.undoDepth(), 1u);
    ASSERT_TRUE(history.undo(doc));
    EXPECT_NE(doc.plane->formula.iterations, 77);
    EXPECT_EQ(doc.plane->view.center, moved.center) << "undo keeps where one looks";
    EXPECT_EQ(doc.plane->view.width, moved.width);
}

TEST(EditorPlaneNavigation, WheelZoomKeepsThePointUnderTheCursorFixed) {
    const PlaneViewRect start{{-0.7436438870371587, 0.1318259042053120}, 3.2};
    const int w = 600, h = 400;
    // Cursor positions in window pixels over a viewport of 800 px showing a 600 px image (the
    // render scale), fractional as a mouse gives them.
    const double viewportW = 800.0, toImage = w / viewportW;
    for (double cx : {0.0, 123.25, 400.0, 799.5})
        for (double cy : {0.0, 77.75, 533.0})
            for (double wheel : {1.0, -1.0, 2.5, 10.0}) {
                PlaneInput in;
                in.cursorX = cx;
                in.cursorY = cy;
                in.wheel = wheel;
                const PlaneViewRect after = navigatePlane(start, in, w, h, viewportW);
                // The plane point under the cursor, before and after.
                auto under = [&](const PlaneViewRect& v) {
                    return v.center + real2(cx * toImage - 0.5 * w, 0.5 * h - cy * toImage) * v.pixelSize(w);
                };
                const real2 a = under(start), b = under(after);
                EXPECT_NEAR(a.x, b.x, 1e-15 * std::max(1.0, std::abs(a.x))) << cx << "," << cy << " wheel " << wheel;
                EXPECT_NEAR(a.y, b.y, 1e-15 * std::max(1.0, std::abs(a.y))) << cx << "," << cy << " wheel " << wheel;
                EXPECT_NEAR(after.width, start.width / std::pow(1.25, wheel), 1e-12 * start.width);
            }
    // The same for a pixel's centre through the renderer's own pixel mapping.
    PlaneInput in;
    in.cursorX = (17 + 0.5) / toImage;
    in.cursorY = (300 + 0.5) / toImage;
    in.wheel = 4.0;
    const PlaneViewRect after = navigatePlane(start, in, w, h, viewportW);
    const real2 a = planePixelPosition(start, w, h, 17, 300, glm::vec2(0.5f));
    const real2 b = planePixelPosition(after, w, h, 17, 300, glm::vec2(0.5f));
    EXPECT_NEAR(glm::length(a - b), 0.0, 1e-14);
}

TEST(EditorPlaneNavigation, DragMovesThePlaneWithTheCursor) {
    const PlaneViewRect start{{0.25, -0.5}, 2.0};
    const int w = 500, h = 300;
    const double viewportW = 1000.0, toImage = w / viewportW;
    PlaneInput in;
    in.dragX = 40.0;
    in.dragY = -24.0;
    const PlaneViewRect after = navigatePlane(start, in, w, h, viewportW);
    // The point that was under pixel p is now under p + drag (in image pixels).
    const real2 before = planePixelPosition(start, w, h, 100, 100, glm::vec2(0.5f));
    const real2 moved =
        planePixelPosition(after, w, h, 100 + int(40 * toImage), 100 + int(-24 * toImage), glm::vec2(0.5f));
    EXPECT_NEAR(before.x, moved.x, 1e-12);
    EXPECT_NEAR(before.y, moved.y, 1e-12);
    EXPECT_EQ(after.width, start.width) << "a drag does not zoom";
    EXPECT_NE(after.center, start.center);
}

TEST(EditorPlaneFiles, OpensSavesAndReopensA2dPresetExactly) {
    TempDir tmp("editor_plane_files");
    EditorState s;
    newDocument(s);
    ASSERT_FALSE(s.doc.isPlane());
    ASSERT_TRUE(openDocument(s, planePresetPath("koch_snowflake.json"))) << s.status.text;
    ASSERT_TRUE(s.doc.isPlane());
    EXPECT_FALSE(isDirty(s));
    EXPECT_EQ(s.doc.plane->formula.start.size(), 6u);
    s.doc.plane->formula.iterations = 4;
    s.doc.plane->view.width = 1.0 / 3.0;
    EXPECT_TRUE(isDirty(s));
    const fs::path file = tmp.dir / "koch.json";
    ASSERT_TRUE(saveDocumentAs(s, file)) << s.status.text;
    EXPECT_FALSE(isDirty(s));
    s.doc.plane->colouring.offset = 0.5;
    ASSERT_TRUE(saveDocument(s)) << s.status.text;
    EXPECT_TRUE(fs::exists(fs::path(file.string() + ".bak"))) << "the previous version is kept";
    EXPECT_EQ(loadPlanePreset(fs::path(file.string() + ".bak")).colouring.offset, 0.0);
    // The saved file is a 2D preset that `fraktal render` and the editor read back as it was.
    ASSERT_TRUE(isPlanePresetFile(file));
    const std::string saved = fingerprint(s.doc);
    EditorState t;
    ASSERT_TRUE(openDocument(t, file)) << t.status.text;
    EXPECT_EQ(fingerprint(t.doc), saved);
    EXPECT_EQ(t.doc.plane->view.width, 1.0 / 3.0);
    // Reset view goes back to the view the file was opened with.
    t.doc.plane->view.width = 1e-9;
    resetPlaneView(t);
    EXPECT_EQ(t.doc.plane->view.width, 1.0 / 3.0);
    // A 3D preset after a 2D one is a 3D document again.
    ASSERT_TRUE(openDocument(t, test::sourceDir() / "presets" / "menger.json"));
    EXPECT_FALSE(t.doc.isPlane());
}

TEST(EditorPlaneFiles, NewPlaneDocumentIsAnUnsavedMandelbrot) {
    EditorState s;
    newPlaneDocument(s);
    ASSERT_TRUE(s.doc.isPlane());
    EXPECT_TRUE(s.file.path.empty());
    EXPECT_EQ(std::string(s.doc.plane->formula.nodes.at(0).block->id), "power");
    EXPECT_EQ(s.planeSelection, (PlaneSelection{PlaneList::Loop, 0}));
}

TEST(EditorPlaneFiles, A2dStillsExrOpensItsEmbeddedPreset) {
    TempDir tmp("editor_plane_exr");
    test::glContext();
    PlaneStillJob job;
    job.preset = loadPlanePreset(planePresetPath("julia.json"));
    job.preset.render.width = 24;
    job.preset.render.height = 16;
    job.preset.render.spp = 1;
    job.preset.view.width = 0.7;  // differs from the file: the EXR's own preset must come back
    job.exr = tmp.dir / "julia.exr";
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    renderPlaneStill(job, color);
    const Document d = loadDocument(job.exr);
    ASSERT_TRUE(d.isPlane());
    EXPECT_EQ(planePresetToJson(*d.plane), planePresetToJson(job.preset));
    EditorState s;
    ASSERT_TRUE(openDocument(s, job.exr)) << s.status.text;
    EXPECT_TRUE(s.file.path.empty()) << "an EXR is an image: Save must ask where the preset goes";
    // A 3D still's EXR stays 3D; an EXR without a preset is a clear error naming the file.
    EXPECT_FALSE(planePresetFromExr(job.exr) == std::nullopt);
    const fs::path notExr = tmp.dir / "bad.exr";
    std::ofstream(notExr) << "not an exr";
    EXPECT_FALSE(openDocument(s, notExr));
    EXPECT_NE(s.status.text.find("bad.exr"), std::string::npos) << s.status.text;
}

TEST(EditorPlaneFiles, AutosaveRecoversA2dDocument) {
    TempDir tmp("editor_plane_autosave");
    Document doc = planeDocument("sierpinski_triangle.json");
    doc.plane->formula.iterations = 3;
    doc.plane->view.center = real2(0.1, 1.0 / 7.0);
    fs::path original;
    const Document back = documentFromRecovery(recoveryText(doc, "/x/tri.json"), "recovery.json", original);
    EXPECT_EQ(original, fs::path("/x/tri.json"));
    ASSERT_TRUE(back.isPlane());
    EXPECT_EQ(fingerprint(back), fingerprint(doc));
    EXPECT_EQ(back.plane->view.center.y, 1.0 / 7.0);
    // A 3D document still round-trips (with its editor section).
    Document scene;
    scene.preset = loadPreset(test::sourceDir() / "presets" / "menger.json");
    scene.view.aaCap = 7;
    const Document sceneBack = documentFromRecovery(recoveryText(scene, ""), "recovery.json", original);
    EXPECT_FALSE(sceneBack.isPlane());
    EXPECT_EQ(fingerprint(sceneBack), fingerprint(scene));
    EXPECT_TRUE(original.empty());
    EXPECT_THROW(documentFromRecovery("[1, 2]", "recovery.json", original), PresetError);
}

TEST(EditorPlaneEdits, SelectionFollowsTheListsAndErrorsNameThe2dNode) {
    PlaneFormula f = loadPlanePreset(planePresetPath("koch_snowflake.json")).formula;
    EXPECT_EQ(clampedSelection(f, {PlaneList::Start, 99}), (PlaneSelection{PlaneList::Start, 5}));
    f.start.clear();
    EXPECT_EQ(clampedSelection(f, {PlaneList::Start, 2}), (PlaneSelection{PlaneList::Loop, 0}));
    f.nodes.clear();
    EXPECT_EQ(clampedSelection(f, {PlaneList::Loop, 0}), (PlaneSelection{PlaneList::Estimator, 0}));
    // Adding with the estimator selected appends to the loop; a full list refuses.
    PlaneSelection sel = addPlaneBlock(f, *findPlaneBlock("scale"), {PlaneList::Estimator, 0});
    EXPECT_EQ(sel, (PlaneSelection{PlaneList::Loop, 0}));
    for (int i = 0; i < kMaxNodes + 3; ++i) sel = addPlaneBlock(f, *findPlaneBlock("scale"), sel);
    EXPECT_EQ(int(f.nodes.size()), kMaxNodes);
    // Parameters are clamped to the declared range.
    const ParamDecl& factor = findPlaneBlock("scale")->params[0];
    ASSERT_TRUE(setPlaneParam(f, {PlaneList::Loop, 0}, 0, 1e9));
    EXPECT_EQ(f.nodes[0].values[0].x, factor.max);
    // The names generatePlaneGLSL gives nodes are the ones the panel finds in a log.
    const PlaneFormula koch = loadPlanePreset(planePresetPath("koch_snowflake.json")).formula;
    const GeneratedFormula g = generatePlaneGLSL(koch);
    EXPECT_EQ(planeNodeNamedInLog(g.nodeNames[2] + ", GLSL line 1: error"), (PlaneSelection{PlaneList::Start, 2}));
    EXPECT_EQ(planeNodeNamedInLog(g.nodeNames[koch.start.size() + 1] + ": error"),
              (PlaneSelection{PlaneList::Loop, 1}));
    EXPECT_EQ(planeNodeNamedInLog(g.nodeNames.back() + ": error"), (PlaneSelection{PlaneList::Estimator, 0}));
    EXPECT_EQ(planeNodeNamedInLog("linker error"), std::nullopt);
}

}  // namespace
}  // namespace fraktal::editor
