#include "app/editor/formula_edits.hpp"

#include <algorithm>
#include <regex>

namespace fraktal::editor {

std::vector<const BlockDesc*> blocksIn(Category category) {
    std::vector<const BlockDesc*> out;
    for (const BlockDesc& b : allBlocks())
        if (b.category == category) out.push_back(&b);
    return out;
}

namespace {
bool validIndex(const Formula& f, int i) { return i >= 0 && i < int(f.nodes.size()); }

Node* nodeAt(Formula& f, int index) {
    if (index == int(f.nodes.size())) return &f.estimator;
    return validIndex(f, index) ? &f.nodes[size_t(index)] : nullptr;
}
}  // namespace

bool addNode(Formula& f, const BlockDesc& block, int insertAt) {
    if (block.isEstimator()) return setEstimator(f, block);
    if (int(f.nodes.size()) >= kMaxNodes) return false;
    if (insertAt < 0 || insertAt > int(f.nodes.size())) insertAt = int(f.nodes.size());
    f.nodes.insert(f.nodes.begin() + insertAt, Node::make(block));
    return true;
}

bool removeNode(Formula& f, int index) {
    if (!validIndex(f, index)) return false;
    f.nodes.erase(f.nodes.begin() + index);
    return true;
}

bool duplicateNode(Formula& f, int index) {
    if (!validIndex(f, index) || int(f.nodes.size()) >= kMaxNodes) return false;
    const Node copy = f.nodes[size_t(index)];
    f.nodes.insert(f.nodes.begin() + index + 1, copy);
    return true;
}

bool moveNode(Formula& f, int from, int to) {
    if (!validIndex(f, from) || !validIndex(f, to) || from == to) return false;
    Node n = std::move(f.nodes[size_t(from)]);
    f.nodes.erase(f.nodes.begin() + from);
    f.nodes.insert(f.nodes.begin() + to, std::move(n));
    return true;
}

bool setNodeEnabled(Formula& f, int index, bool enabled) {
    if (!validIndex(f, index) || f.nodes[size_t(index)].enabled == enabled) return false;
    f.nodes[size_t(index)].enabled = enabled;
    return true;
}

bool setEstimator(Formula& f, const BlockDesc& estimator) {
    if (!estimator.isEstimator()) return false;
    f.estimator = Node::make(estimator);
    return true;
}

bool setParam(Formula& f, int index, int param, const ParamValue& value) {
    Node* n = nodeAt(f, index);
    if (!n || !n->block || param < 0 || param >= int(n->block->params.size())) return false;
    const ParamDecl& d = n->block->params[size_t(param)];
    ParamValue v = glm::clamp(value, vec3(d.min), vec3(d.max));
    if (d.type == ParamType::Float) v.y = v.z = 0.0;
    // A direction must not collapse to zero (the preset reader refuses that too).
    if (d.direction && glm::length(v) == 0.0) return false;
    n->values[size_t(param)] = v;
    return true;
}

void resetParam(Formula& f, int index, int param) {
    Node* n = nodeAt(f, index);
    if (!n || !n->block || param < 0 || param >= int(n->block->params.size())) return;
    n->values[size_t(param)] = n->block->params[size_t(param)].defaultValue;
}

int nodeNamedInLog(const std::string& log, int nodeCount) {
    const std::regex node(R"(node (\d+) \()");
    std::smatch m;
    if (std::regex_search(log, m, node)) return std::stoi(m[1]);
    if (log.find("estimator (") != std::string::npos) return nodeCount;
    return -1;
}

}  // namespace fraktal::editor
