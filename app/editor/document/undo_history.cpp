#include "app/editor/document/undo_history.hpp"

#include <algorithm>
#include <map>
#include <nlohmann/json.hpp>

#include "app/editor/document/lights_edits.hpp"
#include "app/editor/document/timeline_edits.hpp"
#include "core/param_label.hpp"

namespace fraktal::editor {

using nlohmann::json;

namespace {

// The document with the view (camera placement, 2D rectangle) set to a fixed value.
Document withoutView(Document d) {
    const Camera fixed;
    d.preset.camera.position = fixed.position;
    d.preset.camera.target = fixed.target;
    d.preset.camera.up = fixed.up;
    if (d.plane) d.plane->view = PlaneViewRect{};
    return d;
}

// `to` with the view of `from`.
void keepView(Document& to, const Document& from) {
    to.preset.camera.position = from.preset.camera.position;
    to.preset.camera.target = from.preset.camera.target;
    to.preset.camera.up = from.preset.camera.up;
    if (to.plane && from.plane) to.plane->view = from.plane->view;
}

bool isIndex(const std::string& s) { return !s.empty() && s.find_first_not_of("0123456789") == std::string::npos; }

// A JSON pointer's components ("/formula/nodes/0/params/power").
std::vector<std::string> components(const std::string& pointer) {
    std::vector<std::string> parts;
    size_t at = 1;
    while (at <= pointer.size()) {
        const size_t next = std::min(pointer.find('/', at), pointer.size());
        parts.push_back(pointer.substr(at, next - at));
        at = next + 1;
    }
    return parts;
}

std::string nodeName(const Node& n) { return n.block ? std::string(n.block->label) : std::string("block"); }

// Two nodes alike in block, values, switch and schedule (a duplicate and its original).
bool sameNode(const Node& a, const Node& b) { return a.block == b.block && nodeToJson(a) == nodeToJson(b); }

// A node added, duplicated or removed: the first position where the two lists' blocks differ
// names it; an added node like the one before it is a duplicate (Ctrl+D).
std::string nodeCountChange(const std::vector<Node>& before, const std::vector<Node>& after) {
    const bool added = after.size() > before.size();
    const std::vector<Node>& longer = added ? after : before;
    const std::vector<Node>& shorter = added ? before : after;
    size_t i = 0;
    while (i < shorter.size() && shorter[i].block == longer[i].block) ++i;
    if (added && i > 0 && sameNode(longer[i - 1], longer[i])) return "duplicate " + nodeName(longer[i]);
    return (added ? "add " : "remove ") + nodeName(longer[i]);
}

// The same nodes in another order: the one that moved (the others keep their order).
std::string nodeMove(const std::vector<Node>& before, const std::vector<Node>& after) {
    size_t first = 0, last = before.size();
    while (first < last && sameNode(before[first], after[first])) ++first;
    while (last > first && sameNode(before[last - 1], after[last - 1])) --last;
    if (last - first < 2) return "";
    auto shifted = [&](size_t from, size_t to, int by) {
        for (size_t k = from; k < to; ++k)
            if (!sameNode(before[k], after[size_t(int(k) + by)])) return false;
        return true;
    };
    // Down: before[first] lands at last - 1, the ones after it move up by one.
    if (sameNode(before[first], after[last - 1]) && shifted(first + 1, last, -1))
        return "move " + nodeName(before[first]);
    // Up: before[last - 1] lands at first, the ones before it move down by one.
    if (sameNode(before[last - 1], after[first]) && shifted(first, last - 1, 1))
        return "move " + nodeName(before[last - 1]);
    return "";
}

// An edit of the node list in words: a node added, duplicated, removed, moved, switched on or
// off, or the estimator replaced; empty for an edit of values.
std::string nodeListChange(const Formula& before, const Formula& after) {
    const std::vector<Node>&a = before.nodes, &b = after.nodes;
    if (a.size() != b.size()) return nodeCountChange(a, b);
    if (std::string moved = nodeMove(a, b); !moved.empty()) return moved;
    bool sameBlocks = true;
    for (size_t i = 0; i < a.size(); ++i) sameBlocks = sameBlocks && a[i].block == b[i].block;
    if (!sameBlocks) return "";
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].enabled != b[i].enabled) return (b[i].enabled ? "enable " : "disable ") + nodeName(b[i]);
    if (before.estimator.block != after.estimator.block && after.estimator.block)
        return "change of estimator to " + nodeName(after.estimator);
    return "";
}

// A custom GLSL block whose definition (code, parameters, label...) an Apply in its window
// replaced, in the words of that window: "edit of <label>"; empty when none changed.
std::string customBlockChange(const Formula& before, const Formula& after) {
    for (const auto& b : after.customBlocks)
        for (const auto& a : before.customBlocks)
            if (a->definition().id == b->definition().id && customBlockToJson(*a) != customBlockToJson(*b))
                return "edit of " + std::string(b->desc().label);
    return {};
}

// An object beside the fractal or a combined fractal added or removed.
std::string objectListChange(const Formula& before, const Formula& after) {
    const std::vector<SceneObject>&a = before.objects, &b = after.objects;
    if (a.size() != b.size()) {
        const bool added = b.size() > a.size();
        const std::vector<SceneObject>& longer = added ? b : a;
        const std::vector<SceneObject>& shorter = added ? a : b;
        size_t i = 0;
        while (i < shorter.size() && shorter[i].block == longer[i].block) ++i;
        const std::string name = longer[i].block ? std::string(longer[i].block->label) : std::string("an");
        return (added ? "add " : "remove ") + name + " object";
    }
    if (before.fractals.size() != after.fractals.size())
        return after.fractals.size() > before.fractals.size() ? "add fractal" : "remove fractal";
    return "";
}

// A light added, duplicated or removed: the first position where the lists differ names it.
std::string lightListChange(const std::vector<Light>& before, const std::vector<Light>& after) {
    if (before.size() == after.size()) return "";
    const bool added = after.size() > before.size();
    const std::vector<Light>& longer = added ? after : before;
    const std::vector<Light>& shorter = added ? before : after;
    size_t i = 0;
    while (i < shorter.size() && shorter[i] == longer[i]) ++i;
    return (added ? "add " : "remove ") + std::string(lightTypeNames(longer[i].type).label) + " light";
}

// Fields the editor derives from the document after an edit, not set by the user in that step:
// the step factor measured for a new structure (AutoStepFactor) and the structure it was
// measured for. Named only when nothing else changed (the factor set by hand).
bool isDerived(const std::string& pointer) {
    return pointer == "/formula/deFactor" || pointer == "/formula/deFactorMeasuredFor";
}

// JSON names whose panel label is not their name in words (core/preset.cpp, lighting.cpp,
// document.cpp write them; the panels label them). A block parameter's name is its widget's
// label (ParamDecl::name) and is not listed.
const std::map<std::string, std::string, std::less<>>& fieldLabels() {
    static const std::map<std::string, std::string, std::less<>> labels = {
        // Formula panel.
        {"deFactor", "step factor"},
        {"boundRadius", "bound radius"},
        {"enabled", "on/off"},
        {"hitRule", "hit rule"},
        // A node's window of iterations (its From and Before fields).
        {"start", "iteration window"},
        {"stop", "iteration window"},
        // Camera tab.
        {"fovY", "field of view"},
        {"flipVertical", "vertical flip"},
        // Shading tab.
        {"lightColor", "light colour"},
        {"fillColor", "fill colour"},
        {"aoSteps", "ambient occlusion"},
        {"aoDistance", "AO distance"},
        {"aoStrength", "AO strength"},
        {"shadowSteps", "shadows"},
        {"paletteA", "palette"},
        {"paletteB", "palette"},
        {"paletteC", "palette"},
        {"paletteD", "palette"},
        {"fogColor", "fog colour"},
        // Render tab.
        {"maxSteps", "max steps per ray"},
        {"overRelaxation", "over-relaxation"},
        {"maxStepGrowth", "step growth"},
        {"spp", "samples per pixel"},
        {"renderScale", "resolution"},
        {"frameTimeTargetMs", "frame-time target"},
        {"motionMinScale", "lowest motion scale"},
        {"aaCap", "AA cap"},
        {"coneTile", "cone pre-pass tile"},
        {"maxCarryFrames", "colour carry"},
        {"motionFilterRadius", "filter radius"},
        {"pathSppCap", "path spp cap"},
        {"viewSlots", "stored views"},
        // Lights tab.
        {"color", "colour"},
        {"aperture", "aperture radius"},
        {"fStop", "aperture radius"},
    };
    return labels;
}

// A block parameter's label as its widget shows it, lower-cased for a sentence ("change of
// packing", not "change of klein_r"), for the path [..., "nodes", i, "params", name (, index)] of a
// node whose JSON in `document` names a built-in block; empty for any other path.
std::string blockParamLabel(const json& document, std::vector<std::string> parts) {
    while (!parts.empty() && isIndex(parts.back())) parts.pop_back();  // a vector's component
    if (parts.size() < 2 || parts[parts.size() - 2] != "params") return {};
    json::json_pointer node;
    for (size_t i = 0; i + 2 < parts.size(); ++i) node /= parts[i];
    if (!document.contains(node)) return {};
    const json& n = document.at(node);
    if (!n.is_object() || !n.contains("block") || !n["block"].is_string()) return {};
    const BlockDesc* block = findBlock(n["block"].get<std::string>());
    if (!block) return {};
    const int index = block->paramIndex(parts.back());
    if (index < 0) return {};
    std::string label = paramLabel(block->params[size_t(index)]);
    if (!label.empty() && label[0] >= 'A' && label[0] <= 'Z') label[0] = char(label[0] - 'A' + 'a');
    return label;
}

// The fields a change at `parts` with `value` names: each field of an added or removed section,
// else the innermost named one (a block parameter's label, or "bailout", "exposure", ...);
// `document` is the side of the change that holds the path.
template <typename Add>
void nameFields(const json& document, std::vector<std::string> parts, const json& value, const Add& add) {
    if (value.is_object() && !value.empty()) {
        for (auto it = value.begin(); it != value.end(); ++it) {
            parts.push_back(it.key());
            nameFields(document, parts, it.value(), add);
            parts.pop_back();
        }
        return;
    }
    if (std::string label = blockParamLabel(document, parts); !label.empty()) {
        add(std::move(label));
        return;
    }
    for (auto it = parts.rbegin(); it != parts.rend(); ++it)
        if (!isIndex(*it)) {
            add(fieldLabel(*it));
            return;
        }
}

}  // namespace

std::string fieldLabel(const std::string& jsonName) {
    const auto& labels = fieldLabels();
    if (auto it = labels.find(jsonName); it != labels.end()) return it->second;
    // camelCase in words ("fogDensity" -> "fog density"); other names (block parameters) as they are.
    std::string words;
    for (size_t i = 0; i < jsonName.size(); ++i) {
        const char c = jsonName[i];
        if (c >= 'A' && c <= 'Z' && i > 0 && jsonName[i - 1] >= 'a' && jsonName[i - 1] <= 'z')
            words += std::string(" ") + char(c - 'A' + 'a');
        else
            words += c;
    }
    return words;
}

std::string undoKey(const Document& d) { return fingerprint(withoutView(d)); }

std::string describeChange(const Document& before, const Document& after) {
    if (std::string keys = describeAnimationChange(before.preset, after.preset); !keys.empty()) return keys;
    if (!before.plane && !after.plane) {
        const Formula &a = before.preset.formula, &b = after.preset.formula;
        // Before the node list: the nodes of an edited block are bound to its new definition.
        if (std::string block = customBlockChange(a, b); !block.empty()) return block;
        if (std::string nodes = nodeListChange(a, b); !nodes.empty()) return nodes;
        if (std::string objects = objectListChange(a, b); !objects.empty()) return objects;
        if (std::string lights = lightListChange(before.preset.lighting.lights, after.preset.lighting.lights);
            !lights.empty())
            return lights;
    }
    const json a = json::parse(undoKey(before)), b = json::parse(undoKey(after));
    json patch = json::diff(a, b);
    // The factor measured with an edit is part of it, not a second thing it did.
    const bool onlyDerived =
        std::all_of(patch.begin(), patch.end(), [](const json& op) { return isDerived(op.value("path", "")); });
    std::vector<std::string> names;
    auto add = [&](std::string name) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
    };
    for (const json& op : patch) {
        const std::string path = op.value("path", "");
        if (!onlyDerived && isDerived(path)) continue;
        // Fields at their default are not written: an added or removed section names the fields
        // inside it ({"params": {"power": 5.5}} is a change of power).
        const bool removed = op.value("op", "") == "remove";
        const json& value = removed ? a.at(json::json_pointer(path)) : op.value("value", json());
        nameFields(removed ? a : b, components(path), value, add);
    }
    if (names.empty()) return "change";
    std::string text = "change of " + names[0];
    if (names.size() == 2) text += " and " + names[1];
    if (names.size() > 2) text += " and " + std::to_string(names.size() - 1) + " more";
    return text;
}

void UndoHistory::reset(const Document& d) {
    past_.clear();
    future_.clear();
    present_ = d;
    presentKey_ = undoKey(d);
}

bool UndoHistory::commit(const Document& d) {
    std::string key = undoKey(d);
    if (key == presentKey_) {
        present_ = d;  // the same state, viewed from elsewhere
        return false;
    }
    past_.push_back(std::move(present_));
    if (past_.size() > capacity_) past_.pop_front();
    future_.clear();
    present_ = d;
    presentKey_ = std::move(key);
    return true;
}

void UndoHistory::replacePresent(const Document& d) {
    present_ = d;
    presentKey_ = undoKey(d);
}

bool UndoHistory::amendPresent(const std::function<void(Document&)>& derive) {
    derive(present_);
    std::string key = undoKey(present_);
    if (key == presentKey_) return false;
    presentKey_ = std::move(key);
    return true;
}

bool UndoHistory::undo(Document& d) {
    commit(d);
    if (past_.empty()) return false;
    future_.push_front(std::move(present_));
    present_ = std::move(past_.back());
    past_.pop_back();
    keepView(present_, d);
    presentKey_ = undoKey(present_);
    d = present_;
    return true;
}

bool UndoHistory::redo(Document& d) {
    commit(d);
    if (future_.empty()) return false;
    past_.push_back(std::move(present_));
    present_ = std::move(future_.front());
    future_.pop_front();
    keepView(present_, d);
    presentKey_ = undoKey(present_);
    d = present_;
    return true;
}

std::string UndoHistory::undoLabel() const { return past_.empty() ? "" : describeChange(past_.back(), present_); }
std::string UndoHistory::redoLabel() const { return future_.empty() ? "" : describeChange(present_, future_.front()); }

}  // namespace fraktal::editor
