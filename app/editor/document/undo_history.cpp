#include "app/editor/document/undo_history.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "app/editor/document/lights_edits.hpp"
#include "app/editor/document/timeline_edits.hpp"

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

// A node added or removed: the first position where the two lists' blocks differ names it.
std::string nodeListChange(const std::vector<Node>& before, const std::vector<Node>& after) {
    if (before.size() == after.size()) return "";
    const bool added = after.size() > before.size();
    const std::vector<Node>& longer = added ? after : before;
    const std::vector<Node>& shorter = added ? before : after;
    size_t i = 0;
    while (i < shorter.size() && shorter[i].block == longer[i].block) ++i;
    const BlockDesc* b = longer[i].block;
    return (added ? "add " : "remove ") + (b ? std::string(b->label) : std::string("block"));
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

}  // namespace

std::string undoKey(const Document& d) { return fingerprint(withoutView(d)); }

std::string describeChange(const Document& before, const Document& after) {
    if (std::string keys = describeAnimationChange(before.preset, after.preset); !keys.empty()) return keys;
    if (!before.plane && !after.plane)
        if (std::string nodes = nodeListChange(before.preset.formula.nodes, after.preset.formula.nodes); !nodes.empty())
            return nodes;
    if (!before.plane && !after.plane)
        if (std::string lights = lightListChange(before.preset.lighting.lights, after.preset.lighting.lights);
            !lights.empty())
            return lights;
    const json a = json::parse(undoKey(before)), b = json::parse(undoKey(after));
    const json patch = json::diff(a, b);
    std::vector<std::string> names;
    auto add = [&](std::string name) {
        if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
    };
    for (const json& op : patch) {
        const std::string path = op.value("path", "");
        std::vector<std::string> parts = components(path);
        // Fields at their default are not written: an added or removed section names the field
        // inside it ({"params": {"power": 5.5}} is a change of power).
        json value = op.value("op", "") == "remove" ? a.at(json::json_pointer(path)) : op.value("value", json());
        while (value.is_object() && value.size() == 1) {
            parts.push_back(value.begin().key());
            value = json(value.begin().value());
        }
        // The innermost named field: a parameter's name, or "bailout", "exposure", ...
        for (auto it = parts.rbegin(); it != parts.rend(); ++it)
            if (!isIndex(*it)) {
                add(*it);
                break;
            }
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
