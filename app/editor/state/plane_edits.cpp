#include "app/editor/state/plane_edits.hpp"

#include <algorithm>
#include <cmath>
#include <regex>

#include "app/editor/document/node_list_edits.hpp"

namespace fraktal::editor {

std::vector<const PlaneBlockDesc*> planeBlocksIn(Category category) {
    std::vector<const PlaneBlockDesc*> out;
    for (const PlaneBlockDesc& b : allPlaneBlocks())
        if (b.category == category) out.push_back(&b);
    return out;
}

std::vector<PlaneNode>* planeList(PlaneFormula& f, PlaneList list) {
    switch (list) {
        case PlaneList::Start: return &f.start;
        case PlaneList::Loop: return &f.nodes;
        case PlaneList::Estimator: return nullptr;
    }
    return nullptr;
}

PlaneNode* selectedPlaneNode(PlaneFormula& f, const PlaneSelection& sel) {
    std::vector<PlaneNode>* list = planeList(f, sel.list);
    if (!list) return &f.estimator;
    return validNodeIndex(*list, sel.index) ? &(*list)[size_t(sel.index)] : nullptr;
}

PlaneSelection clampedSelection(const PlaneFormula& f, PlaneSelection sel) {
    const std::vector<PlaneNode>& list = sel.list == PlaneList::Start ? f.start : f.nodes;
    if (sel.list == PlaneList::Estimator) return {PlaneList::Estimator, 0};
    if (list.empty()) return f.nodes.empty() ? PlaneSelection{PlaneList::Estimator, 0} : PlaneSelection{};
    sel.index = std::clamp(sel.index, 0, int(list.size()) - 1);
    return sel;
}

PlaneSelection addPlaneBlock(PlaneFormula& f, const PlaneBlockDesc& block, PlaneSelection sel) {
    if (block.isEstimator()) {
        f.estimator = PlaneNode::make(block);
        return {PlaneList::Estimator, 0};
    }
    // With the estimator selected, the block goes at the end of the loop.
    if (sel.list == PlaneList::Estimator) sel = {PlaneList::Loop, int(f.nodes.size()) - 1};
    std::vector<PlaneNode>& list = *planeList(f, sel.list);
    const int at = std::min(sel.index + 1, int(list.size()));
    if (!insertNode(list, PlaneNode::make(block), at)) return sel;
    return {sel.list, at};
}

bool setPlaneParam(PlaneFormula& f, const PlaneSelection& sel, int param, double value) {
    PlaneNode* n = selectedPlaneNode(f, sel);
    if (!n || !n->block || param < 0 || param >= int(n->block->params.size())) return false;
    const ParamDecl& d = n->block->params[size_t(param)];
    n->values[size_t(param)] = ParamValue(std::clamp(value, d.min, d.max), 0.0, 0.0);
    return true;
}

std::optional<PlaneSelection> planeNodeNamedInLog(const std::string& log) {
    std::smatch m;
    // Numbered from 1, as the lists show them (listedNodeName).
    if (std::regex_search(log, m, std::regex(R"(start node (\d+) ")")))
        return PlaneSelection{PlaneList::Start, std::stoi(m[1]) - 1};
    if (std::regex_search(log, m, std::regex(R"(node (\d+) ")")))
        return PlaneSelection{PlaneList::Loop, std::stoi(m[1]) - 1};
    if (log.find("estimator \"") != std::string::npos) return PlaneSelection{PlaneList::Estimator, 0};
    return std::nullopt;
}

double planeWheelZoomFactor(double wheelSteps) { return std::pow(1.25, wheelSteps); }

}  // namespace fraktal::editor

namespace fraktal::editor {

PlaneViewRect navigatePlane(PlaneViewRect view, const PlaneInput& in, int imageWidth, int imageHeight,
                            double viewportWidth) {
    if (imageWidth <= 0 || imageHeight <= 0 || viewportWidth <= 0.0) return view;
    const double toImage = double(imageWidth) / viewportWidth;
    if (in.dragX != 0.0 || in.dragY != 0.0)
        view = planePanned(view, imageWidth, in.dragX * toImage, in.dragY * toImage);
    if (in.wheel != 0.0)
        view = planeZoomedAt(view, imageWidth, imageHeight, in.cursorX * toImage, in.cursorY * toImage,
                             planeWheelZoomFactor(in.wheel));
    return view;
}

}  // namespace fraktal::editor
