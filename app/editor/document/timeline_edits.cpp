#include "app/editor/document/timeline_edits.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

namespace fraktal::editor {

namespace {

Track* findTrackMutable(Animation& a, const std::string& target) { return const_cast<Track*>(findTrack(a, target)); }

Key* keyAtMutable(Track& t, double frame) { return const_cast<Key*>(keyAt(t, frame)); }

void sortKeys(Track& t) {
    std::sort(t.keys.begin(), t.keys.end(), [](const Key& a, const Key& b) { return a.frame < b.frame; });
}

std::string frameText(double frame) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", frame);
    return text;
}

// The key of `after` that `before` lacks (or the other way round), with its frame.
std::optional<double> onlyKeyFrame(const Track& a, const Track& b) {
    for (const Key& k : a.keys)
        if (!keyAt(b, k.frame)) return k.frame;
    return std::nullopt;
}

}  // namespace

int shownLastFrame(const Animation& a) {
    return a.empty() && a.lastFrame <= a.firstFrame ? a.firstFrame + kDefaultTimelineSpan - 1 : a.lastFrame;
}

nlohmann::json timelineJson(const TimelineState& t) {
    using nlohmann::json;
    json markers = json::object();
    for (const auto& [target, at] : t.keyMarkers) markers[target] = {at.first, at.second};
    json j = {{"frame", t.frame},
              {"playing", t.playing},
              {"loop", t.loop},
              {"cameraPath", t.showCameraPath},
              {"bar", {t.bar[0], t.bar[1], t.bar[2], t.bar[3]}},
              {"shownFrames", {t.shownFirst, t.shownLast}},
              {"playButton", {t.playButton[0], t.playButton[1]}},
              {"pathButton", {t.pathButton[0], t.pathButton[1]}},
              {"keyMarkers", markers}};
    j["hovered"] = t.hovered;
    j["firstRow"] = t.firstRow;
    j["selectedKey"] = t.selected ? json{{"target", t.selected->target}, {"frame", t.selected->frame}} : json();
    return j;
}

const Track* findTrack(const Animation& a, const std::string& target) {
    for (const Track& t : a.tracks)
        if (t.target == target) return &t;
    return nullptr;
}

const Key* keyAt(const Track& track, double frame) {
    for (const Key& k : track.keys)
        if (std::abs(k.frame - frame) < 1e-6) return &k;
    return nullptr;
}

bool differsFromTrack(const Preset& p, const Track& track, double frame, const std::vector<double>& value) {
    const bool camera = track.target.rfind("camera.", 0) == 0;
    const std::vector<double> animated = trackValueIn(p, track, camera ? cameraTime(p.animation, frame) : frame);
    if (animated.size() != value.size()) return true;
    // q and -q are the same orientation.
    double sign = 1.0;
    if (track.target == kCameraOrientationTarget) {
        double d = 0.0;
        for (size_t c = 0; c < value.size(); ++c) d += animated[c] * value[c];
        if (d < 0.0) sign = -1.0;
    }
    for (size_t c = 0; c < value.size(); ++c)
        if (std::abs(animated[c] - sign * value[c]) > 1e-9 * std::max(1.0, std::abs(animated[c]))) return true;
    return false;
}

std::vector<double> cameraOrientation(const Camera& c) {
    const glm::dquat q = orientationOf(c.target - c.position, c.up);
    return {q.w, q.x, q.y, q.z};
}

bool addKey(Animation& a, const std::string& target, double frame, std::vector<double> value) {
    Track* t = findTrackMutable(a, target);
    if (!t) {
        a.tracks.push_back(Track{target, Interpolation::Smooth, {Key{frame, std::move(value)}}});
        return true;
    }
    if (Key* k = keyAtMutable(*t, frame)) {
        if (k->value == value) return false;
        k->value = std::move(value);
        return true;
    }
    t->keys.push_back(Key{frame, std::move(value)});
    sortKeys(*t);
    return true;
}

bool deleteKey(Animation& a, const KeyRef& key) {
    Track* t = findTrackMutable(a, key.target);
    const Key* k = t ? keyAt(*t, key.frame) : nullptr;
    if (!k) return false;
    t->keys.erase(t->keys.begin() + (k - t->keys.data()));
    if (t->keys.empty()) a.tracks.erase(a.tracks.begin() + (t - a.tracks.data()));
    return true;
}

bool moveKey(Animation& a, const KeyRef& key, double toFrame) {
    Track* t = findTrackMutable(a, key.target);
    Key* k = t ? keyAtMutable(*t, key.frame) : nullptr;
    if (!k || keyAt(*t, toFrame)) return false;
    k->frame = toFrame;
    sortKeys(*t);
    return true;
}

bool setInterpolation(Animation& a, const std::string& target, Interpolation interpolation) {
    Track* t = findTrackMutable(a, target);
    if (!t || t->interpolation == interpolation) return false;
    t->interpolation = interpolation;
    return true;
}

std::string targetLabel(const Preset& p, const std::string& target) {
    const KeyedParam keyed = keyedParam(p.formula, target);
    const Node* node = keyed.node;
    const std::string& param = keyed.name;
    // The block's label and the parameter, unless the label names it already ("Mandelbulb power").
    if (node && node->block) {
        const std::string label(node->block->label);
        const auto lower = [](std::string t) {
            std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            return t;
        };
        const std::string l = lower(label);
        const bool named =
            l.size() >= param.size() && l.compare(l.size() - param.size(), param.size(), lower(param)) == 0;
        return named ? label : label + " " + param;
    }
    std::string words = target;
    std::replace(words.begin(), words.end(), '.', ' ');
    return words;
}

std::string describeAnimationChange(const Preset& before, const Preset& after) {
    const Animation &a = before.animation, &b = after.animation;
    if (a == b) return "";
    const auto label = [&](const std::string& target) { return targetLabel(after, target); };
    // A track added or removed with its only key, or a key added, removed or moved in one track.
    for (const Track& tb : b.tracks) {
        const Track* ta = findTrack(a, tb.target);
        if (!ta) return "Add key: " + label(tb.target) + " @ " + frameText(tb.keys.front().frame);
        if (*ta == tb) continue;
        if (ta->interpolation != tb.interpolation)
            return "Interpolation: " + label(tb.target) + " " +
                   (tb.interpolation == Interpolation::Constant ? "constant"
                    : tb.interpolation == Interpolation::Linear ? "linear"
                                                                : "smooth");
        const std::optional<double> added = onlyKeyFrame(tb, *ta), removed = onlyKeyFrame(*ta, tb);
        if (added && removed && tb.keys.size() == ta->keys.size())
            return "Move key: " + label(tb.target) + " @ " + frameText(*removed) + " -> " + frameText(*added);
        if (added) return "Add key: " + label(tb.target) + " @ " + frameText(*added);
        if (removed) return "Delete key: " + label(tb.target) + " @ " + frameText(*removed);
        for (const Key& k : tb.keys)
            if (const Key* old = keyAt(*ta, k.frame); old && old->value != k.value)
                return "Set key: " + label(tb.target) + " @ " + frameText(k.frame);
    }
    for (const Track& ta : a.tracks)
        if (!findTrack(b, ta.target))
            return "Delete key: " + label(ta.target) + " @ " + frameText(ta.keys.back().frame);
    if (a.firstFrame != b.firstFrame || a.lastFrame != b.lastFrame) return "change of frame range";
    if (a.fps != b.fps) return "change of fps";
    return "change of animation";
}

PlaybackStep playbackFrame(const Animation& a, int startFrame, double elapsed, bool loop) {
    // A hair over the exact product: 1 s at 24 fps is frame +24, not +23.999...
    const long long advanced = (long long)std::floor(std::max(elapsed, 0.0) * a.fps + 1e-9);
    const long long frame = (long long)startFrame + advanced;
    if (frame <= a.lastFrame) return {int(frame), false};
    if (!loop) return {a.lastFrame, true};
    const long long span = std::max(1, a.frameCount());
    return {int(a.firstFrame + (frame - a.firstFrame) % span), false};
}

void applyAnimationFrame(Preset& p, double frame) {
    if (p.animation.empty()) return;
    const Preset at = presetAtFrame(p, frame);
    // presetAtFrame writes every track into a copy read back from JSON; untracked fields come
    // back as they were, so whole sections can be taken over, but not the formula's blocks.
    p.camera = at.camera;
    p.shading = at.shading;
    p.render = at.render;
    p.lighting.lens = at.lighting.lens;
    // Tracks key the lights' fields, never their number: the lists match.
    if (at.lighting.lights.size() == p.lighting.lights.size()) p.lighting.lights = at.lighting.lights;
    p.lighting.environment = at.lighting.environment;
    Formula& f = p.formula;
    f.iterations = at.formula.iterations;
    f.bailout = at.formula.bailout;
    f.boundRadius = at.formula.boundRadius;
    f.deFactor = at.formula.deFactor;
    for (size_t i = 0; i < f.nodes.size() && i < at.formula.nodes.size(); ++i)
        f.nodes[i].values = at.formula.nodes[i].values;
    f.estimator.values = at.formula.estimator.values;
}

}  // namespace fraktal::editor
