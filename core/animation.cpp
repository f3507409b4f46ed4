#include "core/animation.hpp"

#include <algorithm>
#include <cmath>

#include "core/json_reader.hpp"
#include "core/preset.hpp"

namespace fraktal {

using nlohmann::json;

namespace {

constexpr const char* kInterpolationNames[] = {"constant", "linear", "smooth"};
// The sections whose numeric fields can be keyed ("render" cannot: size and samples are per sequence).
constexpr const char* kKeyableSections[] = {"formula.",         "camera.", "shading.",
                                            "colorManagement.", "lights[", "environment."};
constexpr int kMaxKeysPerTrack = 100000;
constexpr int kMaxTracks = 1000;
constexpr int kArcLengthSamplesPerFrame = 16;

glm::dquat toQuat(const std::vector<double>& v) { return glm::dquat(v[0], v[1], v[2], v[3]); }
std::vector<double> fromQuat(const glm::dquat& q) { return {q.w, q.x, q.y, q.z}; }

// Index of the last key at or before `frame` (0 before the first key).
size_t segmentStart(const std::vector<Key>& keys, double frame) {
    const auto after =
        std::upper_bound(keys.begin(), keys.end(), frame, [](double f, const Key& k) { return f < k.frame; });
    return after == keys.begin() ? 0 : size_t(after - keys.begin()) - 1;
}

// Catmull-Rom tangent (per frame) at key i over non-uniform key times; one-sided at the ends.
double tangent(const std::vector<Key>& keys, size_t i, size_t c) {
    const size_t lo = i == 0 ? 0 : i - 1, hi = std::min(i + 1, keys.size() - 1);
    if (lo == hi) return 0.0;
    return (keys[hi].value[c] - keys[lo].value[c]) / (keys[hi].frame - keys[lo].frame);
}

// Quaternion log and exp of unit quaternions (pure quaternions for log), for squad.
glm::dquat quatLog(const glm::dquat& q) {
    const double v = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (v < 1e-12) return glm::dquat(0.0, 0.0, 0.0, 0.0);
    const double s = std::atan2(v, q.w) / v;
    return glm::dquat(0.0, q.x * s, q.y * s, q.z * s);
}
glm::dquat quatExp(const glm::dquat& q) {
    const double a = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z);
    if (a < 1e-12) return glm::dquat(1.0, 0.0, 0.0, 0.0);
    const double s = std::sin(a) / a;
    return glm::dquat(std::cos(a), q.x * s, q.y * s, q.z * s);
}

// Keys' quaternions with signs chosen so that each is in the hemisphere of the previous one (q and
// -q are the same rotation; interpolating across hemispheres would take the long way round).
std::vector<glm::dquat> alignedQuaternions(const std::vector<Key>& keys) {
    std::vector<glm::dquat> q;
    for (const Key& k : keys) {
        glm::dquat r = glm::normalize(toQuat(k.value));
        if (!q.empty() && glm::dot(q.back(), r) < 0.0) r = -r;
        q.push_back(r);
    }
    return q;
}

// Shoemake's squad control point for key i: q_i exp(-(log(q_i^-1 q_i+1) + log(q_i^-1 q_i-1)) / 4).
glm::dquat squadControl(const std::vector<glm::dquat>& q, size_t i) {
    const glm::dquat prev = q[i == 0 ? 0 : i - 1], next = q[std::min(i + 1, q.size() - 1)];
    const glm::dquat inv = glm::conjugate(q[i]);
    const glm::dquat a = quatLog(inv * next), b = quatLog(inv * prev);
    return glm::normalize(q[i] * quatExp(glm::dquat(0.0, -(a.x + b.x) / 4, -(a.y + b.y) / 4, -(a.z + b.z) / 4)));
}

// Slerp without choosing the shorter arc (squad's inner interpolations must not flip).
glm::dquat slerpDirect(const glm::dquat& a, const glm::dquat& b, double t) {
    const double c = std::clamp(glm::dot(a, b), -1.0, 1.0);
    if (c > 1.0 - 1e-12) return glm::normalize(a * (1.0 - t) + b * t);
    const double angle = std::acos(c), s = std::sin(angle);
    return a * (std::sin((1.0 - t) * angle) / s) + b * (std::sin(t * angle) / s);
}

std::vector<double> evaluateOrientation(const Track& track, Interpolation how, double frame) {
    const std::vector<Key>& keys = track.keys;
    const std::vector<glm::dquat> q = alignedQuaternions(keys);
    const size_t i = segmentStart(keys, frame);
    if (frame <= keys.front().frame || i + 1 >= keys.size() || how == Interpolation::Constant)
        return fromQuat(q[frame <= keys.front().frame ? 0 : i]);
    const double t = (frame - keys[i].frame) / (keys[i + 1].frame - keys[i].frame);
    if (how == Interpolation::Linear) return fromQuat(slerpShortest(q[i], q[i + 1], t));
    const glm::dquat s0 = squadControl(q, i), s1 = squadControl(q, i + 1);
    return fromQuat(
        glm::normalize(slerpDirect(slerpDirect(q[i], q[i + 1], t), slerpDirect(s0, s1, t), 2.0 * t * (1.0 - t))));
}

// `track` at `frame`, read with `how` in place of the track's own interpolation.
std::vector<double> evaluateWith(const Track& track, Interpolation how, double frame) {
    if (track.target == kCameraOrientationTarget) return evaluateOrientation(track, how, frame);
    const std::vector<Key>& keys = track.keys;
    if (frame <= keys.front().frame) return keys.front().value;
    if (frame >= keys.back().frame) return keys.back().value;
    const size_t i = segmentStart(keys, frame);
    if (how == Interpolation::Constant) return keys[i].value;
    const Key &a = keys[i], &b = keys[i + 1];
    const double span = b.frame - a.frame, t = (frame - a.frame) / span;
    std::vector<double> out(a.value.size());
    for (size_t c = 0; c < out.size(); ++c) {
        if (how == Interpolation::Linear) {
            out[c] = a.value[c] + (b.value[c] - a.value[c]) * t;
            continue;
        }
        // Cubic Hermite basis.
        const double t2 = t * t, t3 = t2 * t;
        out[c] = (2 * t3 - 3 * t2 + 1) * a.value[c] + (t3 - 2 * t2 + t) * span * tangent(keys, i, c) +
                 (-2 * t3 + 3 * t2) * b.value[c] + (t3 - t2) * span * tangent(keys, i + 1, c);
    }
    return out;
}

const Track* findTrack(const Animation& a, const std::string& target) {
    for (const Track& t : a.tracks)
        if (t.target == target) return &t;
    return nullptr;
}

bool isCameraTarget(const std::string& target) { return target.rfind("camera.", 0) == 0; }

// The JSON pointer of `target` in a preset document. "formula.estimator.params.NAME" (what the
// editor keys for the closing estimator, so that adding or removing a node keeps the track on it)
// is the last of the document's nodes, where a file lists the estimator.
json::json_pointer targetPointer(const json& document, const std::string& target) {
    if (const auto p = parseParamTarget(target); p && p->estimator) {
        const json::json_pointer nodes("/formula/nodes");
        const size_t count = document.contains(nodes) && document.at(nodes).is_array() ? document.at(nodes).size() : 0;
        if (count > 0) return json::json_pointer(pointerFromPath(paramTarget(count - 1, p->name)));
    }
    return json::json_pointer(pointerFromPath(target));
}

// Writes `value` at `target` (a field path) into a preset document.
void setField(json& document, const std::string& target, const std::vector<double>& value) {
    json& field = document[targetPointer(document, target)];
    if (value.size() == 1)
        field = value[0];
    else
        field = json(value);
}

// The tracks of `animation` written into `document` (a preset without its animation) at `frame`.
void applyTracks(const Preset& animated, json& document, double frame) {
    const Animation& animation = animated.animation;
    const double cameraFrame = cameraTime(animation, frame);
    const Track* orientation = nullptr;
    for (const Track& t : animation.tracks) {
        if (t.target == kCameraOrientationTarget) {
            orientation = &t;
            continue;
        }
        setField(document, t.target, trackValueIn(animated, t, isCameraTarget(t.target) ? cameraFrame : frame));
    }
    if (!orientation) return;
    json& camera = document["camera"];
    const auto vec = [](const json& j) { return vec3(j[0].get<double>(), j[1].get<double>(), j[2].get<double>()); };
    const vec3 position = vec(camera["position"]);
    const double distance = std::max(1e-6, length(vec(camera["target"]) - position));
    const glm::dquat q = toQuat(evaluateTrack(*orientation, cameraFrame));
    camera["target"] = vecJson(position + (q * vec3(0.0, 0.0, -1.0)) * distance);
    camera["up"] = vecJson(q * vec3(0.0, 1.0, 0.0));
}

json stillDocument(const Preset& preset) {
    json j = presetToJson(preset);
    j.erase("animation");
    return j;
}

}  // namespace

glm::dquat slerpShortest(glm::dquat a, glm::dquat b, double t) {
    if (glm::dot(a, b) < 0.0) b = -b;
    return slerpDirect(a, b, t);
}

glm::dquat orientationOf(const vec3& forward, const vec3& up) {
    const CameraBasis b = basisLookingAlong(forward, up);
    // Columns: camera x, y, z (= -forward) in world space.
    const mat3 m(b.right, b.up, -b.forward);
    return glm::normalize(glm::quat_cast(m));
}

std::vector<double> evaluateTrack(const Track& track, double frame) {
    return evaluateWith(track, track.interpolation, frame);
}

std::string paramTarget(size_t node, const std::string& param) {
    return "formula.nodes[" + std::to_string(node) + "].params." + param;
}

std::string estimatorParamTarget(const std::string& param) { return "formula.estimator.params." + param; }

std::optional<ParamTarget> parseParamTarget(const std::string& target) {
    const std::string nodes = "formula.nodes[", estimator = estimatorParamTarget(""), params = "].params.";
    if (target.rfind(estimator, 0) == 0) return ParamTarget{true, 0, target.substr(estimator.size())};
    if (target.rfind(nodes, 0) != 0) return std::nullopt;
    const size_t close = target.find(params);
    const std::string index = close == std::string::npos ? "" : target.substr(nodes.size(), close - nodes.size());
    if (index.empty() || index.size() > 8 || index.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    return ParamTarget{false, std::stoul(index), target.substr(close + params.size())};
}

KeyedParam keyedParam(const Formula& f, const std::string& target) {
    KeyedParam k;
    const auto p = parseParamTarget(target);
    // A file lists the closing estimator last among its nodes.
    if (!p || (!p->estimator && p->node > f.nodes.size())) return k;
    k.node = p->estimator || p->node == f.nodes.size() ? &f.estimator : &f.nodes[p->node];
    k.name = p->name;
    if (k.node->block)
        if (const int i = k.node->block->paramIndex(k.name); i >= 0) k.decl = &k.node->block->params[size_t(i)];
    return k;
}

void remapNodeTracks(Animation& animation, const std::vector<int>& newIndexOf, size_t newCount) {
    std::vector<Track> kept;
    for (Track& t : animation.tracks) {
        const auto p = parseParamTarget(t.target);
        if (p && !p->estimator && p->node <= newIndexOf.size()) {
            const int to = p->node == newIndexOf.size() ? int(newCount) : newIndexOf[p->node];
            if (to < 0) continue;
            t.target = paramTarget(size_t(to), p->name);
        }
        kept.push_back(std::move(t));
    }
    animation.tracks = std::move(kept);
}

void dropEstimatorTracks(Animation& animation, size_t nodeCount) {
    std::erase_if(animation.tracks, [&](const Track& t) {
        const auto p = parseParamTarget(t.target);
        return p && (p->estimator || p->node == nodeCount);
    });
}

bool stepsAtKeys(const Preset& preset, const std::string& target) {
    const ParamDecl* d = keyedParam(preset.formula, target).decl;
    return d && d->type == ParamType::Toggle;
}

Interpolation interpolationIn(const Preset& preset, const Track& track) {
    return stepsAtKeys(preset, track.target) ? Interpolation::Constant : track.interpolation;
}

std::vector<double> trackValueIn(const Preset& preset, const Track& track, double frame) {
    return evaluateWith(track, interpolationIn(preset, track), frame);
}

double cameraTime(const Animation& animation, double frame) {
    const Track* path = animation.evenCameraSpeed ? findTrack(animation, "camera.position") : nullptr;
    if (!path || path->keys.size() < 2) return frame;
    const double f0 = path->keys.front().frame, f1 = path->keys.back().frame;
    if (frame <= f0 || frame >= f1) return frame;
    // Cumulative length of the path, sampled finely in key time, then inverted.
    const int samples = std::max(2, int(std::ceil((f1 - f0) * kArcLengthSamplesPerFrame)));
    std::vector<double> length(size_t(samples) + 1, 0.0);
    std::vector<double> previous = evaluateTrack(*path, f0);
    for (int s = 1; s <= samples; ++s) {
        const std::vector<double> p = evaluateTrack(*path, f0 + (f1 - f0) * s / samples);
        double d2 = 0.0;
        for (size_t c = 0; c < p.size(); ++c) d2 += (p[c] - previous[c]) * (p[c] - previous[c]);
        length[size_t(s)] = length[size_t(s) - 1] + std::sqrt(d2);
        previous = p;
    }
    if (length.back() <= 0.0) return frame;
    const double wanted = length.back() * (frame - f0) / (f1 - f0);
    const size_t s = size_t(std::lower_bound(length.begin(), length.end(), wanted) - length.begin());
    if (s == 0) return f0;
    const double segment = length[s] - length[s - 1];
    const double within = segment > 0.0 ? (wanted - length[s - 1]) / segment : 0.0;
    return f0 + (f1 - f0) * (double(s - 1) + within) / samples;
}

Animation parseAnimation(const ReadContext& context, const json& j, const Preset& still) {
    FieldReader r(context, j, "animation");
    Animation a;
    a.firstFrame = r.integer("firstFrame", 0, 0, 10000000);
    a.lastFrame = r.integer("lastFrame", a.firstFrame, 0, 10000000);
    if (a.lastFrame < a.firstFrame) r.fail("lastFrame is before firstFrame", "lastFrame");
    a.fps = r.number("fps", a.fps, 1e-3, 1000.0);
    const std::string speed = r.string("cameraSpeed", "keyed", 64);
    if (speed != "keyed" && speed != "even")
        r.fail("expected \"keyed\" or \"even\", found \"" + speed + "\"", "cameraSpeed");
    a.evenCameraSpeed = speed == "even";
    const json& tracks = r.at("tracks");
    if (!tracks.is_array()) r.fail("expected an array of tracks, found " + FieldReader::typeName(tracks), "tracks");
    if (tracks.size() > size_t(kMaxTracks)) r.fail("more than " + std::to_string(kMaxTracks) + " tracks", "tracks");
    const json stillJson = stillDocument(still);
    for (size_t i = 0; i < tracks.size(); ++i) {
        const std::string path = r.child("tracks") + "[" + std::to_string(i) + "]";
        if (!tracks[i].is_object()) throw PresetError(context.file, path, "expected a track object");
        FieldReader t(context, tracks[i], path);
        Track track;
        track.target = t.string("target", "", 256);
        if (track.target.empty()) t.fail("missing required field", "target");
        if (std::none_of(std::begin(kKeyableSections), std::end(kKeyableSections),
                         [&](const char* s) { return track.target.rfind(s, 0) == 0; }))
            t.fail("'" + track.target +
                       "' cannot be keyed (keyable: formula.*, camera.*, shading.*, colorManagement.*, lights[i].*, "
                       "environment.*)",
                   "target");
        if (findTrack(a, track.target)) t.fail("'" + track.target + "' has two tracks", "target");
        const std::string interpolation = t.string("interpolation", "smooth", 64);
        const auto name = std::find(std::begin(kInterpolationNames), std::end(kInterpolationNames), interpolation);
        if (name == std::end(kInterpolationNames))
            t.fail("expected \"constant\", \"linear\" or \"smooth\", found \"" + interpolation + "\"", "interpolation");
        track.interpolation = Interpolation(name - std::begin(kInterpolationNames));
        const json& keys = t.at("keys");
        const std::string keysPath = t.child("keys");
        if (!keys.is_array() || keys.empty()) t.fail("expected a non-empty array of keys", "keys");
        if (keys.size() > size_t(kMaxKeysPerTrack)) t.fail("too many keys", "keys");
        const bool orientation = track.target == kCameraOrientationTarget;
        for (size_t k = 0; k < keys.size(); ++k) {
            const std::string keyPath = keysPath + "[" + std::to_string(k) + "]";
            if (!keys[k].is_object()) throw PresetError(context.file, keyPath, "expected a key object");
            FieldReader kr(context, keys[k], keyPath);
            Key key;
            key.frame = kr.number("frame", 0.0, -1e7, 1e7);
            if (!kr.has("frame")) kr.fail("missing required field", "frame");
            const json& v = kr.at("value");
            if (v.is_number()) {
                key.value = {kr.checkNumber(v, kr.child("value"), -1e7, 1e7)};
            } else if (v.is_array() && (v.size() == 3 || v.size() == 4)) {
                for (size_t c = 0; c < v.size(); ++c)
                    key.value.push_back(
                        kr.checkNumber(v[c], kr.child("value") + "[" + std::to_string(c) + "]", -1e7, 1e7));
            } else {
                kr.fail("expected a number or an array of 3 or 4 numbers, found " + FieldReader::typeName(v), "value");
            }
            if (orientation) {
                if (key.value.size() != 4) kr.fail("an orientation is a quaternion [w, x, y, z]", "value");
                if (glm::length(toQuat(key.value)) < 1e-9) kr.fail("a zero quaternion is no rotation", "value");
            } else if (key.value.size() == 4) {
                kr.fail("only camera.orientation takes 4 numbers", "value");
            }
            if (!track.keys.empty() && key.value.size() != track.keys[0].value.size())
                kr.fail("every key of a track has the same number of values", "value");
            if (!track.keys.empty() && key.frame <= track.keys.back().frame)
                kr.fail("keys must be in increasing frame order", "frame");
            kr.finish();
            // The preset's own reader checks the value at its field: a parameter that does not
            // exist, a vector where a number is expected, a value outside the field's range.
            if (!orientation) {
                json probe = stillJson;
                try {
                    const json::json_pointer pointer = targetPointer(probe, track.target);
                    const json::json_pointer parent = pointer.parent_pointer();
                    // A section or a block's "params" left out for being at its defaults is no missing field.
                    const bool omittedSection = !parent.empty() && parent.parent_pointer().empty();
                    if (!probe.contains(parent) && !omittedSection &&
                        !(!parent.empty() && parent.back() == "params" && probe.contains(parent.parent_pointer())))
                        throw PresetError(context.file, track.target, "no such field");
                    setField(probe, track.target, key.value);
                    parsePreset(probe.dump(), context.file);
                } catch (const PresetError& e) {
                    // A field that does not exist is the target's fault; a value the field refuses, the key's.
                    // (A parameter error reads "block N 'id': unknown parameter ...".)
                    const bool badTarget = e.reason() == "no such field" ||
                                           e.reason().find("unknown parameter") != std::string::npos ||
                                           e.reason().rfind("unknown", 0) == 0;
                    const std::string where = e.field() == track.target || e.field().empty() ? "" : e.field() + ": ";
                    throw PresetError(context.file, badTarget ? path + ".target" : keyPath + ".value",
                                      "'" + track.target + "': " + where + e.reason());
                } catch (const json::exception&) {
                    throw PresetError(context.file, path + ".target", "'" + track.target + "' is not a field path");
                }
            }
            track.keys.push_back(std::move(key));
        }
        t.finish();
        a.tracks.push_back(std::move(track));
    }
    r.finish();
    return a;
}

json animationJson(const Animation& a) {
    json j = json::object();
    if (a.firstFrame != 0) j["firstFrame"] = a.firstFrame;
    j["lastFrame"] = a.lastFrame;
    if (a.fps != 24.0) j["fps"] = a.fps;
    if (a.evenCameraSpeed) j["cameraSpeed"] = "even";
    json tracks = json::array();
    for (const Track& t : a.tracks) {
        json track = {{"target", t.target}};
        if (t.interpolation != Interpolation::Smooth)
            track["interpolation"] = kInterpolationNames[int(t.interpolation)];
        json keys = json::array();
        for (const Key& k : t.keys)
            keys.push_back({{"frame", k.frame}, {"value", k.value.size() == 1 ? json(k.value[0]) : json(k.value)}});
        track["keys"] = keys;
        tracks.push_back(track);
    }
    j["tracks"] = tracks;
    return j;
}

Preset presetAtFrame(const Preset& animated, double frame) {
    json j = stillDocument(animated);
    applyTracks(animated, j, frame);
    return parsePreset(j.dump(), animated.name.empty() ? "animated preset" : animated.name);
}

}  // namespace fraktal
