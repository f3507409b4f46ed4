// Undo/redo by whole-document snapshots. The editor commits after each finished edit (a drag
// released, a checkbox clicked), so one Ctrl+Z undoes one gesture. A document is a few
// kilobytes, so snapshots are simpler and safer than inverse operations: restoring a snapshot
// restores every field exactly. Where one looks from is not an edit: the 3D camera's position,
// target and up and the 2D view's rectangle are left out of the steps (moving the view records
// nothing, undo keeps the current view), though they are saved with the document.
#pragma once

#include <deque>
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

    bool canUndo() const { return !past_.empty(); }
    bool canRedo() const { return !future_.empty(); }
    // Replace `d` with the previous / next state, keeping d's view. `d` should equal the present
    // state; any uncommitted change in it is committed first so that it can be redone.
    bool undo(Document& d);
    bool redo(Document& d);

    const Document& present() const { return present_; }
    size_t undoDepth() const { return past_.size(); }
    size_t redoDepth() const { return future_.size(); }
    // What Undo / Redo would do, for the Edit menu: "change of scale", "add Box fold", ...;
    // empty when there is nothing to undo / redo.
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
// What changed from `before` to `after`, in words (the names of the changed fields, or the
// block added or removed).
std::string describeChange(const Document& before, const Document& after);

}  // namespace fraktal::editor
