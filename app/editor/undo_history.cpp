#include "app/editor/undo_history.hpp"

namespace fraktal::editor {

void UndoHistory::reset(const Document& d) {
    past_.clear();
    future_.clear();
    present_ = d;
    presentKey_ = fingerprint(d);
}

bool UndoHistory::commit(const Document& d) {
    std::string key = fingerprint(d);
    if (key == presentKey_) return false;
    past_.push_back(std::move(present_));
    if (past_.size() > capacity_) past_.pop_front();
    future_.clear();
    present_ = d;
    presentKey_ = std::move(key);
    return true;
}

bool UndoHistory::undo(Document& d) {
    commit(d);
    if (past_.empty()) return false;
    future_.push_front(std::move(present_));
    present_ = std::move(past_.back());
    past_.pop_back();
    presentKey_ = fingerprint(present_);
    d = present_;
    return true;
}

bool UndoHistory::redo(Document& d) {
    commit(d);
    if (future_.empty()) return false;
    past_.push_back(std::move(present_));
    present_ = std::move(future_.front());
    future_.pop_front();
    presentKey_ = fingerprint(present_);
    d = present_;
    return true;
}

}  // namespace fraktal::editor
