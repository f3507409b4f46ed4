// The editor's UI-independent rules: undo/redo restores every state exactly, value edits do
// not recompile while structure edits do, and the fly-speed rule.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "app/editor/document/document.hpp"
#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/preset_files.hpp"
#include "app/editor/document/undo_history.hpp"
#include "app/editor/input/camera_controller.hpp"
#include "app/editor/input/fly_speed.hpp"
#include "app/editor/state/actions.hpp"
#include "core/animation.hpp"
#include "core/scene/scene_import.hpp"
#include "core/scene/scene_revision.hpp"
#include "editor_test_support.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

// A scripted sequence of edits of every kind the editor makes.
std::vector<std::function<void(Document&)>> scriptedEdits() {
    return {
        [](Document& d) { setParam(d.preset.formula, 0, 0, vec3(7.25, 0, 0)); },  // mandelbulb power
        [](Document& d) { d.preset.formula.iterations = 9; },
        [](Document& d) { addNode(d.preset.formula, *findBlock("box_fold"), 0); },
        [](Document& d) { duplicateNode(d.preset.formula, 0); },
        [](Document& d) { moveNode(d.preset.formula, 0, 2); },
        [](Document& d) { setNodeEnabled(d.preset.formula, 1, false); },
        [](Document& d) { d.preset.formula.nodes[1].period = 2; },
        [](Document& d) { setEstimator(d.preset.formula, *findBlock("escape_linear")); },
        [](Document& d) { removeNode(d.preset.formula, 3); },
        [](Document& d) { d.preset.camera.fovY = 61.5; },
        [](Document& d) { d.viewSlots[2] = d.preset.camera; },
        [](Document& d) { d.preset.render.exposure = -1.25; },
        [](Document& d) { d.preset.render.view = "ACES"; },
        [](Document& d) { d.preset.shading.paletteD = vec3(0.0, 0.33, 0.67); },
        [](Document& d) { d.preset.shading.shadowSteps = 0; },
        [](Document& d) { d.view.stepsPerFrame = 12; },
        [](Document& d) { d.preset.formula.bailout = 1.0 / 7.0; },
    };
}

TEST(EditorUndo, ScriptedSequenceUndoesAndRedoesToEveryStateExactly) {
    Document doc = test::documentFrom("mandelbulb.json");
    UndoHistory history;
    history.reset(doc);
    std::vector<std::string> states{fingerprint(doc)};
    for (const auto& edit : scriptedEdits()) {
        edit(doc);
        ASSERT_TRUE(history.commit(doc)) << "each scripted edit changes the document";
        states.push_back(fingerprint(doc));
    }
    // Every state differs from the one before it, so the comparison below can fail.
    for (size_t i = 1; i < states.size(); ++i) ASSERT_NE(states[i], states[i - 1]);

    for (size_t i = states.size() - 1; i-- > 0;) {
        ASSERT_TRUE(history.undo(doc));
        EXPECT_EQ(fingerprint(doc), states[i]) << "after undo back to state " << i;
    }
    EXPECT_FALSE(history.undo(doc));
    EXPECT_EQ(fingerprint(doc), states.front());
    // The first state is also structurally the loaded preset (same doubles, same blocks).
    EXPECT_EQ(doc.preset.formula.structureKey(), test::shippedPreset("mandelbulb.json").formula.structureKey());
    EXPECT_EQ(doc.preset.formula.nodes[0].values[0].x, 8.0);

    for (size_t i = 1; i < states.size(); ++i) {
        ASSERT_TRUE(history.redo(doc));
        EXPECT_EQ(fingerprint(doc), states[i]) << "after redo to state " << i;
    }
    EXPECT_FALSE(history.redo(doc));
    // Exact doubles, not just a matching text form.
    EXPECT_EQ(doc.preset.formula.bailout, 1.0 / 7.0);
    EXPECT_EQ(doc.preset.camera.fovY, 61.5);
}

TEST(EditorUndo, CameraMovesRecordNoStepAndUndoKeepsTheCamera) {
    Document doc = test::documentFrom("mandelbulb.json");
    UndoHistory history;
    history.reset(doc);
    setParam(doc.preset.formula, 0, 0, vec3(5.5, 0, 0));
    ASSERT_TRUE(history.commit(doc));
    doc.preset.camera.position = vec3(0.3, 2.5, 1.0 / 3.0);
    doc.preset.camera.target = vec3(0.1, 0.0, 0.0);
    EXPECT_FALSE(history.commit(doc)) << "an orbit is not an edit";
    EXPECT_EQ(history.undoDepth(), 1u);
    EXPECT_EQ(history.undoLabel(), "change of power");
    ASSERT_TRUE(history.undo(doc));
    EXPECT_EQ(doc.preset.formula.nodes[0].values[0].x, 8.0);
    EXPECT_EQ(doc.preset.camera.position, vec3(0.3, 2.5, 1.0 / 3.0)) << "undo keeps where one looks";
    EXPECT_EQ(history.redoLabel(), "change of power");
}

// Apply in the GLSL block window replaces the block's definition: one step, named after the
// block, that Undo takes back to the code before.
TEST(EditorUndo, ApplyingAnEditedGlslBlockIsOneStepNamedAfterIt) {
    Document doc;
    doc.preset = importSceneFile(test::sourceDir() / "tests/data/frag_import/menger.frag").preset;
    UndoHistory history;
    history.reset(doc);
    CustomBlock::Definition d = doc.preset.formula.customBlocks.at(0)->definition();
    const std::string before = d.glsl;
    d.glsl += "\nfloat unusedHelper(float x) { return x; }\n";
    ASSERT_EQ(upsertCustomBlock(doc.preset.formula, d), "");
    ASSERT_TRUE(history.commit(doc));
    EXPECT_EQ(history.undoDepth(), 1u);
    EXPECT_EQ(history.undoLabel(), "edit of " + std::string(doc.preset.formula.estimator.block->label));
    ASSERT_TRUE(history.undo(doc));
    EXPECT_EQ(doc.preset.formula.customBlocks.at(0)->definition().glsl, before);
}

TEST(EditorUndo, LabelsSayWhatUndoAndRedoWillDo) {
    Document doc = test::documentFrom("mandelbox.json");
    UndoHistory history;
    history.reset(doc);
    addNode(doc.preset.formula, *findBlock("rotate"), 1);
    history.commit(doc);
    EXPECT_EQ(history.undoLabel(), "add Rotate");
    removeNode(doc.preset.formula, 0);
    history.commit(doc);
    EXPECT_EQ(history.undoLabel(), "remove Box fold");
    doc.preset.formula.bailout = 50.0;
    doc.preset.render.exposure = 0.5;
    history.commit(doc);
    EXPECT_EQ(history.undoLabel(), "change of bailout and exposure");
    history.undo(doc);
    EXPECT_EQ(history.redoLabel(), "change of bailout and exposure");
    EXPECT_EQ(history.undoLabel(), "remove Box fold");
}

TEST(EditorUndo, NewEditAfterUndoDropsTheRedoBranch) {
    Document doc = test::documentFrom("menger.json");
    UndoHistory history;
    history.reset(doc);
    doc.preset.formula.iterations = 3;
    history.commit(doc);
    history.undo(doc);
    ASSERT_TRUE(history.canRedo());
    doc.preset.shading.fogDensity = 2.0;
    EXPECT_TRUE(history.commit(doc));
    EXPECT_FALSE(history.canRedo());
    EXPECT_FALSE(history.commit(doc)) << "an unchanged document records nothing";
}

TEST(EditorUndo, EditorSectionRoundTripsThroughTheSavedPreset) {
    Document doc = test::documentFrom("mandelbox.json");
    doc.view.aaCap = 5;
    doc.view.reprojection = false;
    doc.view.maxCarryFrames = 7;
    doc.view.motionFilter = false;
    doc.view.motionFilterRadius = 1.25;
    doc.view.coarseHits = false;
    doc.view.pathTraceAtRest = true;
    doc.view.pathSppCap = 64;
    // The Render and Shading tabs edit the preset's own sections: a saved preset carries them.
    doc.preset.shading.lightDirection = vec3(0.1, 0.2, 0.3);
    doc.preset.render.view = "ACES";
    doc.preset.render.exposure = 0.75;
    doc.viewSlots[1] = doc.preset.camera;
    const fs::path dir = fs::temp_directory_path() / ("fraktal_editor_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path file = dir / "scene.json";
    Document stored = doc;
    storeEditorSection(stored);
    savePresetFile(file, stored.preset);
    savePresetFile(file, stored.preset);  // second save keeps a .bak of the first
    EXPECT_TRUE(fs::exists(fs::path(file.string() + ".bak")));
    Document back;
    back.preset = loadPreset(file);
    loadEditorSection(back);
    EXPECT_EQ(fingerprint(back), fingerprint(doc));
    EXPECT_EQ(back.preset.shading, doc.preset.shading);
    EXPECT_EQ(back.preset.render, doc.preset.render);
    EXPECT_EQ(back.view, doc.view);
    fs::remove_all(dir);
}

TEST(EditorRecompile, ValueEditsKeepTheProgramStructureEditsRecompile) {
    // The viewport recompiles when the frame's scene revision says the structure changed
    // (scene::sceneChange, the one owner of "what changed"); a value edit only restarts.
    Preset p = test::shippedPreset("hybrid_menger_octahedral.json");
    const scene::SceneRevision compiled = scene::sceneRevision(p);
    EXPECT_TRUE(scene::sceneChange(nullptr, compiled).structure) << "no program yet";

    // Values: parameters, iterations, bailout, bound, factor, estimator parameters.
    Formula& f = p.formula;
    setParam(f, 2, 0, vec3(2.5, 0, 0));
    setParam(f, int(f.nodes.size()), 0, vec3(0.9, 1.1, 1.0));
    f.iterations = 7;
    f.bailout = 50.0;
    f.boundRadius = 3.0;
    f.deFactor = 0.8;
    const scene::SceneChange values = scene::sceneChange(&compiled, scene::sceneRevision(p));
    EXPECT_FALSE(values.structure);
    EXPECT_TRUE(values.restarts());

    // Each structure edit on its own needs a new program, once.
    const Preset base = p;
    const std::vector<std::pair<const char*, std::function<void(Formula&)>>> structural{
        {"add", [](Formula& g) { addNode(g, *findBlock("sphere_fold")); }},
        {"remove", [](Formula& g) { removeNode(g, 0); }},
        {"duplicate", [](Formula& g) { duplicateNode(g, 1); }},
        {"reorder", [](Formula& g) { moveNode(g, 0, 3); }},
        {"disable", [](Formula& g) { setNodeEnabled(g, 4, false); }},
        {"period", [](Formula& g) { g.nodes[0].period = 3; }},
        {"estimator", [](Formula& g) { setEstimator(g, *findBlock("sphere")); }},
    };
    for (const auto& [name, edit] : structural) {
        Preset g = base;
        edit(g.formula);
        const scene::SceneRevision recompiled = scene::sceneRevision(g);
        EXPECT_TRUE(scene::sceneChange(&compiled, recompiled).structure) << name;
        EXPECT_FALSE(scene::sceneChange(&recompiled, scene::sceneRevision(g)).structure)
            << name << ": compiled once, no second compile";
    }
}

TEST(EditorFormulaEdits, ParametersAreClampedToTheDeclaredRange) {
    Formula f = test::shippedPreset("mandelbulb.json").formula;
    const ParamDecl& power = f.nodes[0].block->params[0];
    setParam(f, 0, 0, vec3(1e9, 0, 0));
    EXPECT_EQ(f.nodes[0].values[0].x, power.max);
    resetParam(f, 0, 0);
    EXPECT_EQ(f.nodes[0].values[0], power.defaultValue);
    EXPECT_FALSE(removeNode(f, 99));
    EXPECT_FALSE(moveNode(f, 0, 99));
}

TEST(EditorFormulaEdits, CompileErrorNamesTheNode) {
    // The log numbers nodes from 1, as the list shows them.
    EXPECT_EQ(nodeNamedInLog("GLSL compile error in x:\nnode 3 \"Box fold\" (box_fold), GLSL line 2: error: ...", 5),
              2);
    EXPECT_EQ(nodeNamedInLog("estimator \"Box\" (box), GLSL line 1: error", 5), 5);
    EXPECT_EQ(nodeNamedInLog("link error", 5), -1);
}

TEST(EditorFlySpeed, SpeedIsProportionalToTheDistanceToTheSurface) {
    // A sphere of radius 1: the DE is exact, so the rule can be checked against the truth.
    Formula f;
    f.iterations = 0;
    f.boundRadius = 2.0;
    f.estimator = Node::make(*findBlock("sphere"));
    FlyRule rule;
    rule.speedPerDistance = 2.0;
    for (double r : {1.05, 1.2, 1.5, 1.9}) {
        const vec3 eye(0.0, r, 0.0);
        EXPECT_NEAR(safeDistance(f, eye), r - 1.0, 1e-12);
        EXPECT_NEAR(flySpeed(f, eye, rule), 2.0 * (r - 1.0), 1e-12);
    }
    EXPECT_LT(flySpeed(f, vec3(1.01, 0, 0), rule), flySpeed(f, vec3(1.5, 0, 0), rule));
}

TEST(EditorFlySpeed, OutsideTheBoundTheDistanceIsStillALowerBound) {
    Formula f;
    f.iterations = 0;
    f.boundRadius = 2.0;
    f.estimator = Node::make(*findBlock("sphere"));
    for (double r : {2.5, 4.0, 10.0}) {
        const double d = safeDistance(f, vec3(r, 0, 0));
        EXPECT_LE(d, r - 1.0 + 1e-12) << "never more than the true distance";
        EXPECT_GT(d, r - 2.0) << "and more than the distance to the bound sphere";
    }
}

TEST(EditorFlySpeed, NoFrameStepCrossesTheSurfaceEvenWithALongFrame) {
    // Fly straight at a Menger sponge with absurdly long frames: the eye must never get inside.
    const Preset menger = test::shippedPreset("menger.json");
    const Formula& f = menger.formula;
    vec3 eye(0.5, 0.5, 3.0);  // in front of a solid corner column of the sponge
    const vec3 towards(0.0, 0.0, -1.0);
    double lastDistance = 0.0;
    for (int frame = 0; frame < 200; ++frame) {
        const vec3 step = flyStep(f, eye, towards, /*dt=*/5.0, /*boost=*/4.0);
        EXPECT_LE(length(step), 0.5 * safeDistance(f, eye) + 1e-15);
        eye += step;
        const double d = safeDistance(f, eye);
        ASSERT_GT(d, 0.0) << "frame " << frame << ": the eye went through the surface";
        ASSERT_FALSE(evaluate(f, eye).inside) << "frame " << frame;
        lastDistance = d;
    }
    EXPECT_LT(lastDistance, 1e-3) << "and it did get close: the rule slows down, it does not stop early";
}

TEST(EditorCamera, OrbitKeepsTheDistanceAndFlyKeepsTheLookDistance) {
    Camera cam;
    cam.position = vec3(0, 0, 4);
    CameraControls controls;
    CameraInput in;
    in.rotateDrag = vec2(120, -40);
    ASSERT_TRUE(orbitCamera(cam, in, controls));
    EXPECT_NEAR(length(cam.position - cam.target), 4.0, 1e-9);
    EXPECT_GT(std::abs(cam.position.x), 0.5);

    const Formula f = test::shippedPreset("mandelbulb.json").formula;
    const double look = length(cam.target - cam.position);
    CameraInput fly;
    fly.move = vec3(0, 0, 1);
    fly.dt = 0.1;
    const vec3 before = cam.position;
    ASSERT_TRUE(flyCamera(cam, f, fly, controls));
    EXPECT_NEAR(length(cam.target - cam.position), look, 1e-9);
    EXPECT_NEAR(length(cam.position - before), std::min(0.1 * safeDistance(f, before), 0.5 * safeDistance(f, before)),
                1e-9);
}

TEST(EditorFiles, RecentListIsMostRecentFirstWithoutDuplicates) {
    std::vector<std::string> recent;
    pushRecent(recent, "/tmp/a.json");
    pushRecent(recent, "/tmp/b.json");
    pushRecent(recent, "/tmp/./a.json");
    ASSERT_EQ(recent.size(), 2u);
    EXPECT_EQ(recent[0], "/tmp/a.json");
    for (int i = 0; i < 20; ++i) pushRecent(recent, "/tmp/x" + std::to_string(i) + ".json", 10);
    EXPECT_EQ(recent.size(), 10u);
}

TEST(EditorFiles, UnsavedMarkFollowsEditsAndSaves) {
    EditorState s;
    const fs::path dir = fs::temp_directory_path() / ("fraktal_editor_dirty_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    ASSERT_TRUE(openDocument(s, fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "menger.json"));
    EXPECT_FALSE(isDirty(s));
    s.doc.preset.formula.iterations = 2;
    EXPECT_TRUE(isDirty(s));
    ASSERT_TRUE(saveDocumentAs(s, dir / "m.json"));
    EXPECT_FALSE(isDirty(s));
    EXPECT_FALSE(openDocument(s, dir / "missing.json"));
    EXPECT_TRUE(s.status.error);
    EXPECT_NE(s.status.text.find("missing.json"), std::string::npos);
    fs::remove_all(dir);
}

// Node-list edits keep the animation's parameter tracks on the nodes they key: inserting,
// duplicating and moving renumber them, removing a node or replacing the estimator drops its
// tracks, and the edited document still loads (every remaining track names a parameter it has).
TEST(FormulaEditsWithTracks, TracksFollowTheirNodes) {
    Preset p = parsePreset(R"({
  "format": "fraktal-preset", "version": 3,
  "formula": {"nodes": [{"block": "mandelbulb"}, {"block": "add_c"}, {"block": "quaternion_julia"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "animation": {"lastFrame": 10, "tracks": [
    {"target": "formula.nodes[0].params.power", "keys": [{"frame": 0, "value": 4}, {"frame": 10, "value": 8}]},
    {"target": "formula.nodes[1].params.weight", "keys": [{"frame": 0, "value": 0.5}, {"frame": 10, "value": 1}]},
    {"target": "formula.nodes[2].params.slice", "keys": [{"frame": 0, "value": 0}, {"frame": 10, "value": 0.5}]}
  ]}
})",
                           "tracks.json");
    ASSERT_EQ(p.animation.tracks.size(), 3u);
    const auto targets = [&] {
        std::vector<std::string> t;
        for (const Track& track : p.animation.tracks) t.push_back(track.target);
        return t;
    };
    const auto reloads = [&] { EXPECT_NO_THROW(parsePreset(serializePreset(p), "edited")); };

    ASSERT_TRUE(addNode(p, *findBlock("rotate"), 0));
    EXPECT_EQ(targets(), (std::vector<std::string>{"formula.nodes[1].params.power", "formula.nodes[2].params.weight",
                                                   "formula.nodes[3].params.slice"}));
    reloads();
    ASSERT_TRUE(moveNode(p, 0, 2));  // rotate after add_c: mandelbulb 0, add_c 1, rotate 2
    EXPECT_EQ(targets(), (std::vector<std::string>{"formula.nodes[0].params.power", "formula.nodes[1].params.weight",
                                                   "formula.nodes[3].params.slice"}));
    reloads();
    ASSERT_TRUE(duplicateNode(p, 0));  // the copy has no tracks
    EXPECT_EQ(targets(), (std::vector<std::string>{"formula.nodes[0].params.power", "formula.nodes[2].params.weight",
                                                   "formula.nodes[4].params.slice"}));
    reloads();
    ASSERT_TRUE(removeNode(p, 0));
    EXPECT_EQ(targets(), (std::vector<std::string>{"formula.nodes[1].params.weight", "formula.nodes[3].params.slice"}));
    EXPECT_DOUBLE_EQ(presetAtFrame(p, 10).formula.nodes[1].values[0].x, 1.0);  // add_c's weight, still keyed
    reloads();
    ASSERT_TRUE(setEstimator(p, *findBlock("escape_linear")));
    EXPECT_EQ(targets(), (std::vector<std::string>{"formula.nodes[1].params.weight"}));
    reloads();
}

}  // namespace
}  // namespace fraktal::editor

// A formula with a custom GLSL block (no CPU evaluation) must not break the fly rule: outside
// the bound the distance to the bound sphere, inside a crawl.
TEST(EditorFlySpeed, CustomGlslFormulaFallsBackToTheBound) {
    const fraktal::Preset p =
        fraktal::loadPreset(std::string(FRAKTAL_SOURCE_DIR) + "/tests/custom_presets/twisted_mandelbulb.json");
    ASSERT_FALSE(p.formula.cpuEvaluable());
    EXPECT_NEAR(fraktal::editor::safeDistance(p.formula, fraktal::vec3(0.0, 0.0, 4.0)), 4.0 - p.formula.boundRadius,
                1e-12);
    EXPECT_EQ(fraktal::editor::safeDistance(p.formula, fraktal::vec3(0.0, 0.0, 1.0)), 0.0);
    const fraktal::editor::FlyRule rule;
    EXPECT_EQ(fraktal::editor::flySpeed(p.formula, fraktal::vec3(0.0, 0.0, 1.0), rule), rule.escapeSpeed);
}
