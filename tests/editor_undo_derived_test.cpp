// Values the editor derives in the background belong to the edit that caused them: the step
// factor measured after a change of structure (AutoStepFactor) is never an undo step of its own,
// never drops the redo branch, and comes back with its edit on undo and redo. And the Edit menu
// says what a step does in the artist's words ("remove Rotate", "change of palette"), not in the
// preset's JSON names ("change of deFactor", "change of paletteA and 3 more").
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <thread>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/undo_history.hpp"
#include "app/editor/state/actions.hpp"
#include "core/param_label.hpp"
#include "core/scene/formula_fit.hpp"
#include "editor_test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

// What the editor does when a measurement for the document's structure ends: the factor is
// written into the document and into the undo history's present state when that state has the
// measured structure (actions.cpp, updateDerivedValues).
void factorMeasured(Document& doc, UndoHistory& history, double factor) {
    doc.preset.formula.deFactor = factor;
    const std::string structure = doc.preset.formula.structureKey();
    history.amendPresent([&](Document& d) {
        if (d.preset.formula.structureKey() == structure) d.preset.formula.deFactor = factor;
    });
}

struct Edit {
    const char* preset;
    std::function<void(Preset&)> apply;
    const char* label;
};

// Every edit of structure the issue names: add, remove (Del), a node's switch, duplicate (Ctrl+D).
std::vector<Edit> structureEdits() {
    return {
        {"mandelbulb.json", [](Preset& p) { addNode(p, *findBlock("rotate"), 1); }, "add Rotate"},
        {"mandelbox.json", [](Preset& p) { removeNode(p, 0); }, "remove Box fold"},
        {"mandelbox.json", [](Preset& p) { setNodeEnabled(p.formula, 1, false); }, "disable Sphere fold"},
        {"kleinian.json", [](Preset& p) { duplicateNode(p, 0); }, "duplicate Kleinian (Jos Leys)"},
    };
}

// The issue: an edit, then the factor measured for the new structure some seconds later (the
// check's further rounds). The factor joins the edit's step: one step, named by the edit; one
// undo brings back the state before the edit, factor and all; redo the edit with the measured
// factor, without measuring again.
TEST(UndoDerived, AFactorMeasuredAfterAnEditJoinsTheEditsStep) {
    for (const Edit& edit : structureEdits()) {
        SCOPED_TRACE(edit.label);
        Document doc = test::documentFrom(edit.preset);
        UndoHistory history;
        history.reset(doc);
        const std::string before = fingerprint(doc);

        edit.apply(doc.preset);
        factorMeasured(doc, history, 0.61);  // the settled rounds, in the frame of the edit
        ASSERT_TRUE(history.commit(doc));
        factorMeasured(doc, history, 0.47);  // the further rounds, seconds later
        const std::string after = fingerprint(doc);
        EXPECT_FALSE(history.commit(doc)) << "the measured factor is no step of its own";
        EXPECT_EQ(history.undoDepth(), 1u);
        EXPECT_EQ(history.undoLabel(), edit.label);

        ASSERT_TRUE(history.undo(doc));
        EXPECT_EQ(fingerprint(doc), before) << "one undo takes the edit and its factor back";
        EXPECT_EQ(history.redoLabel(), edit.label);
        ASSERT_TRUE(history.redo(doc));
        EXPECT_EQ(fingerprint(doc), after) << "redo brings the edit back with its measured factor";
        EXPECT_EQ(doc.preset.formula.deFactor, 0.47);
        EXPECT_FALSE(history.canRedo());
    }
}

// Undo brings back a structure; its factor measured again (or the rest of its measurement) lands
// in the restored state: the redo branch stays, and redo does the edit again.
TEST(UndoDerived, AFactorMeasuredAfterUndoKeepsRedo) {
    for (const Edit& edit : structureEdits()) {
        SCOPED_TRACE(edit.label);
        Document doc = test::documentFrom(edit.preset);
        UndoHistory history;
        history.reset(doc);
        const double own = doc.preset.formula.deFactor;
        edit.apply(doc.preset);
        factorMeasured(doc, history, 0.61);
        ASSERT_TRUE(history.commit(doc));
        const std::string edited = fingerprint(doc);

        ASSERT_TRUE(history.undo(doc));
        factorMeasured(doc, history, own * 0.9);  // the structure before the edit, measured again
        EXPECT_FALSE(history.commit(doc));
        EXPECT_EQ(history.undoDepth(), 0u);
        ASSERT_TRUE(history.canRedo()) << "a measurement does not drop the redo branch";
        EXPECT_EQ(history.redoLabel(), edit.label);
        ASSERT_TRUE(history.redo(doc));
        EXPECT_EQ(fingerprint(doc), edited);
        ASSERT_TRUE(history.undo(doc));
        EXPECT_EQ(doc.preset.formula.deFactor, own * 0.9) << "undo brings the factor measured for that state";
    }
}

// A measurement for a structure the history has not recorded yet (an edit of the frame, not
// committed) leaves the present state alone: the factor goes with the edit when it is committed.
TEST(UndoDerived, AFactorForAnUncommittedEditWaitsForItsCommit) {
    Document doc = test::documentFrom("mandelbulb.json");
    UndoHistory history;
    history.reset(doc);
    const std::string before = fingerprint(doc);
    addNode(doc.preset, *findBlock("rotate"), 1);
    factorMeasured(doc, history, 0.5);
    EXPECT_EQ(fingerprint(history.present()), before);
    ASSERT_TRUE(history.commit(doc));
    EXPECT_EQ(history.undoLabel(), "add Rotate");
    ASSERT_TRUE(history.undo(doc));
    EXPECT_EQ(fingerprint(doc), before);
}

// The editor itself (EditorState and its actions, as the frame loop calls them), measuring for
// real: new document, add Rotate, Del, the factor measured to the end; one Ctrl+Z brings Rotate
// back, nothing measured since lands as a step, and Ctrl+Y removes Rotate again.
TEST(UndoDerived, EditorUndoesAndRedoesADeleteAcrossTheMeasurement) {
    EditorState s;
    newDocument(s);
    const std::string opened = fingerprint(s.doc);
    // One frame of the editor: the derived values, then the commit of the finished gesture.
    auto frame = [&] {
        updateDerivedValues(s);
        s.history.commit(s.doc);
    };
    auto measuredToTheEnd = [&] {
        test::framesWhile([&] { return s.stepFactor.refining() || s.stepFactor.measuredKey.empty(); }, frame);
        ASSERT_FALSE(s.stepFactor.refining());
    };
    auto blocks = [&] {
        std::string ids;
        for (const Node& n : s.doc.preset.formula.nodes) ids += std::string(n.block->id) + " ";
        return ids;
    };

    ASSERT_TRUE(addNode(s.doc.preset, *findBlock("rotate"), 1));
    fitFormulaAfterEdit(s.doc.preset);
    frame();
    EXPECT_EQ(s.history.undoLabel(), "add Rotate");
    ASSERT_TRUE(removeNode(s.doc.preset, 1));
    fitFormulaAfterEdit(s.doc.preset);
    frame();
    measuredToTheEnd();
    const std::string removed = fingerprint(s.doc);
    const double factor = s.doc.preset.formula.deFactor;
    std::printf("mandelbulb measured %.3f on %d rays in %.2f s\n", s.stepFactor.measured, s.stepFactor.rays,
                s.stepFactor.seconds);
    EXPECT_EQ(s.history.undoDepth(), 2u) << s.history.undoLabel();
    EXPECT_EQ(s.history.undoLabel(), "remove Rotate");

    undo(s);
    frame();
    EXPECT_EQ(blocks(), "mandelbulb rotate add_c ") << "the first Ctrl+Z brings Rotate back";
    EXPECT_EQ(s.status.text, "Undo remove Rotate");
    measuredToTheEnd();  // whatever is measured for the restored structure joins its state
    EXPECT_EQ(s.history.undoDepth(), 1u);
    ASSERT_TRUE(s.history.canRedo()) << "the measurement after undo dropped the redo branch";
    EXPECT_EQ(s.history.redoLabel(), "remove Rotate");

    redo(s);
    frame();
    EXPECT_EQ(blocks(), "mandelbulb add_c ") << "Ctrl+Y removes Rotate again";
    EXPECT_EQ(fingerprint(s.doc), removed);
    EXPECT_EQ(s.doc.preset.formula.deFactor, factor) << "the factor measured for it comes back";
    EXPECT_FALSE(s.stepFactor.refining()) << "a structure measured to the end is not measured again";
    frame();
    EXPECT_EQ(s.history.undoDepth(), 2u);
    EXPECT_FALSE(s.history.canRedo());

    undo(s);
    undo(s);
    frame();
    EXPECT_EQ(fingerprint(s.doc), opened) << "two Ctrl+Z: the new document as it opened";
    EXPECT_FALSE(s.stepFactor.refining()) << "the opened structure keeps its own factor";
}

// Undoing a value edit keeps the structure: the measurement running for it goes on (it is not
// started again), and when it ends its factor lands in the state undo brought back, as no step.
TEST(UndoDerived, UndoingAValueEditLetsTheMeasurementRunOn) {
    EditorState s;
    newDocument(s);
    auto frame = [&] {
        updateDerivedValues(s);
        s.history.commit(s.doc);
    };
    ASSERT_TRUE(addNode(s.doc.preset, *findBlock("rotate"), 1));
    fitFormulaAfterEdit(s.doc.preset);
    frame();
    // The settled rounds run on a worker; the rotated Mandelbulb's tail then calls for further
    // rounds (the case this test needs).
    test::framesWhile([&] { return s.stepFactor.measuring(); }, frame);
    ASSERT_TRUE(s.stepFactor.refining()) << "the settled rounds covered the tail: nothing runs on to undo beside";
    const auto since = s.stepFactor.measuringSince;
    s.doc.preset.formula.iterations = 10;
    frame();
    undo(s);
    frame();
    EXPECT_EQ(s.doc.preset.formula.iterations, 12);
    EXPECT_TRUE(s.stepFactor.refining()) << "undoing a value edit stopped the measurement";
    EXPECT_EQ(s.stepFactor.measuringSince, since) << "undoing a value edit measured again";
    ASSERT_TRUE(test::framesWhile([&] { return s.stepFactor.refining(); }, frame));
    EXPECT_EQ(s.doc.preset.formula.deFactor, s.stepFactor.measured);
    EXPECT_EQ(s.history.present().preset.formula.deFactor, s.stepFactor.measured);
    EXPECT_EQ(s.history.undoLabel(), "add Rotate");
    EXPECT_EQ(s.history.redoLabel(), "change of iterations") << "the measurement kept the redo branch";
}

// Labels in the artist's words: the edit where the node list says what it was, else the changed
// fields as the panels label them; the factor measured with an edit is not named beside it.
TEST(UndoDerived, LabelsUseThePanelsWords) {
    const Document bulb = test::documentFrom("mandelbulb.json");
    auto label = [&](const std::function<void(Document&)>& edit, const Document& from) {
        Document after = from;
        edit(after);
        return describeChange(from, after);
    };
    EXPECT_EQ(label([](Document& d) { d.preset.formula.deFactor = 0.5; }, bulb), "change of step factor");
    EXPECT_EQ(label(
                  [](Document& d) {
                      setParam(d.preset.formula, 0, 0, vec3(5.0, 0, 0));
                      d.preset.formula.deFactor = 0.5;
                  },
                  bulb),
              "change of power");
    EXPECT_EQ(label(
                  [](Document& d) {
                      d.preset.shading.paletteA = vec3(0.1);
                      d.preset.shading.paletteB = vec3(0.2);
                      d.preset.shading.paletteC = vec3(0.3);
                      d.preset.shading.paletteD = vec3(0.4);
                  },
                  bulb),
              "change of palette");
    // The window a node runs in, with the factor measured for its new structure and the tag of
    // that structure.
    EXPECT_EQ(label(
                  [](Document& d) {
                      d.preset.formula.nodes[0].start = 2;
                      d.preset.formula.nodes[0].stop = 5;
                      d.preset.formula.deFactor = 0.5;
                      d.preset.formula.deFactorMeasuredFor = "measured";
                  },
                  bulb),
              "change of iteration window");
    EXPECT_EQ(label([](Document& d) { d.preset.formula.nodes[0].period = 2; }, bulb), "change of period");
    EXPECT_EQ(label([](Document& d) { d.preset.camera.fovY = 30.0; }, bulb), "change of field of view");
    EXPECT_EQ(label([](Document& d) { d.preset.shading.fogDensity = 0.3; }, bulb), "change of fog density");
    EXPECT_EQ(label([](Document& d) { d.preset.formula.boundRadius = 2.0; }, bulb), "change of bound radius");
    EXPECT_EQ(label([](Document& d) { addObject(d.preset.formula, *findObject("sphere")); }, bulb),
              "add Sphere object");
    EXPECT_EQ(label([](Document& d) { setEstimator(d.preset, *findBlock("escape_log")); }, bulb),
              "change of estimator to " + std::string(findBlock("escape_log")->label));

    const Document box = test::documentFrom("mandelbox.json");
    const int radius = findBlock("sphere_fold")->paramIndex("min_radius");
    EXPECT_EQ(label([&](Document& d) { setParam(d.preset.formula, 1, radius, vec3(0.3, 0, 0)); }, box),
              "change of min radius")
        << "a parameter is named as its widget shows it";
    // A declared label ("Packing") rather than the preset's name (klein_r).
    const Document kleinian = test::documentFrom("kleinian.json");
    const int packing = findBlock("kleinian")->paramIndex("klein_r");
    ASSERT_GE(packing, 0);
    EXPECT_EQ(paramLabel(findBlock("kleinian")->params[size_t(packing)]), "Packing");
    EXPECT_EQ(label([&](Document& d) { setParam(d.preset.formula, 0, packing, vec3(1.9, 0, 0)); }, kleinian),
              "change of packing");
    EXPECT_EQ(label(
                  [](Document& d) {
                      setNodeEnabled(d.preset.formula, 0, false);
                      d.preset.formula.deFactor = 0.3;
                  },
                  box),
              "disable Box fold");
    Document off = box;
    setNodeEnabled(off.preset.formula, 0, false);
    EXPECT_EQ(label([](Document& d) { setNodeEnabled(d.preset.formula, 0, true); }, off), "enable Box fold");
    EXPECT_EQ(label([](Document& d) { moveNode(d.preset, 0, 2); }, box), "move Box fold");
    EXPECT_EQ(label([](Document& d) { moveNode(d.preset, 2, 0); }, box), "move Scale");
    EXPECT_EQ(label([](Document& d) { duplicateNode(d.preset, 1); }, box), "duplicate Sphere fold");
    EXPECT_EQ(label([](Document& d) { removeNode(d.preset, 1); }, box), "remove Sphere fold");

    EXPECT_EQ(fieldLabel("deFactor"), "step factor");
    EXPECT_EQ(fieldLabel("paletteC"), "palette");
    EXPECT_EQ(fieldLabel("shadowSoftness"), "shadow softness");
    EXPECT_EQ(fieldLabel("fixed_radius"), "fixed_radius");
}

}  // namespace
}  // namespace fraktal::editor
