// Undo/redo by whole-document snapshots. The editor commits after each finished edit (a drag
// released, a checkbox clicked), so one Ctrl+Z undoes one gesture. A document is a few
// kilobytes, so snapshots are simpler and safer than inverse operations: restoring a snapshot
// restores every field exactly. Where one looks from is not an edit: the 3D camera's position,
// target and up and the 2D view's rectangle are left out of the steps (moving the view records
// nothing, undo keeps the current view), though they are saved with the document.
//
// Values the editor derives from the document in the background (the step factor measured for a
// new structure, AutoStepFactor) are no step of their own: they belong to the edit that made the
// structure. They amend the present state in place (amendPresent), so that one Ctrl+Z takes the
// edit and its factor back together, redo is kept, and a redo brings the measured factor back.
#pragma once

#include <deque>
#include <functional>
#include <string>

#include "app/editor/document/document.hpp"

namespace fraktal::editor {

class UndoHistory {
   public:
    explicit UndoHistory(size_t capacity = 512) : capacity_(capacity) {}

    // Forgets all history; `d` becomes the present state (after open / new).
    void reset(const Document& d);
    // Records `d` as a new state if it differs from the present one other than in the view;
    // drops the redo branch. Returns whether a state was recorded.
    bool commit(const Document& d);

    // Replaces the present state without recording a step: the same state shown at another
    // animation frame (the animation's values written into it), which is no edit.
    void replacePresent(const Document& d);

    // A value derived from the present state (the step factor measured for its structure) joins
    // the step that made that state: `derive` changes the present state in place (the top step's
    // "after", and the "before" of the step Redo would do). No step is recorded, the redo branch
    // stays. Returns whether the present state changed.
    bool amendPresent(const std::function<void(Document&)>& derive);

    bool canUndo() const { return !past_.empty(); }
    bool canRedo() const { return !future_.empty(); }
    // Replace `d` with the previous / next state, keeping d's view. `d` should equal the present
    // state; any uncommitted change in it is committed first so that it can be redone.
    bool undo(Document& d);
    bool redo(Document& d);

    const Document& present() const { return present_; }
    size_t undoDepth() const { return past_.size(); }
    size_t redoDepth() const { return future_.size(); }
    // What Undo / Redo would do, for the Edit menu, in the panels' words: "add Box fold",
    // "disable Rotate", "duplicate Kleinian", "change of palette", ...; empty when there is
    // nothing to undo / redo.
    std::string undoLabel() const;
    std::string redoLabel() const;

   private:
    size_t capacity_;
    std::deque<Document> past_;
    std::deque<Document> future_;
    Document present_;
    std::string presentKey_;
};

// The document's state as undo compares it: the fingerprint without the view.
std::string undoKey(const Document& d);
// What changed from `before` to `after`, in the artist's words: the node added, removed,
// duplicated, moved, enabled or disabled; the light or object added or removed; else the changed
// fields as the panels label them (fieldLabel). The step factor measured with a structure change
// is not named beside the edit that caused it.
std::string describeChange(const Document& before, const Document& after);
// A document field's JSON name as the panels label it: "deFactor" -> "step factor", "paletteB"
// -> "palette", "fovY" -> "field of view"; a block parameter's name (ParamDecl::name, what its
// widget shows) as it is; any other camelCase name in words ("fogDensity" -> "fog density").
std::string fieldLabel(const std::string& jsonName);

}  // namespace fraktal::editor
