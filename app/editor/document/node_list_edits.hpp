// Edits of one node list (add, remove, duplicate, move, enable), for any node type with the
// fields of core/formula.hpp's Node (block, values, enabled, period, phase). The 2D formula
// panel edits its start and loop lists with them (app/editor/state/plane_edits.hpp). Each returns
// false and leaves the list alone when the edit is not possible (an index out of range, or
// kMaxNodes reached).
#pragma once

#include <vector>

#include "core/formula.hpp"

namespace fraktal::editor {

template <class NodeT>
bool validNodeIndex(const std::vector<NodeT>& list, int i) {
    return i >= 0 && i < int(list.size());
}

template <class NodeT>
bool insertNode(std::vector<NodeT>& list, NodeT node, int at) {  // at < 0 or past the end: append
    if (int(list.size()) >= kMaxNodes) return false;
    if (at < 0 || at > int(list.size())) at = int(list.size());
    list.insert(list.begin() + at, std::move(node));
    return true;
}

template <class NodeT>
bool removeNodeAt(std::vector<NodeT>& list, int i) {
    if (!validNodeIndex(list, i)) return false;
    list.erase(list.begin() + i);
    return true;
}

template <class NodeT>
bool duplicateNodeAt(std::vector<NodeT>& list, int i) {  // the copy goes right after the original
    if (!validNodeIndex(list, i)) return false;
    return insertNode(list, NodeT(list[size_t(i)]), i + 1);
}

template <class NodeT>
bool moveNodeWithin(std::vector<NodeT>& list, int from, int to) {  // `to`: where the node ends
    if (!validNodeIndex(list, from) || !validNodeIndex(list, to) || from == to) return false;
    NodeT n = std::move(list[size_t(from)]);
    list.erase(list.begin() + from);
    list.insert(list.begin() + to, std::move(n));
    return true;
}

}  // namespace fraktal::editor
