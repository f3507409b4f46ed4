// Keyframe animation of a preset: tracks of keys on any numeric field of the formula (block
// parameters by node and name), the camera (position, target, up, field of view, and orientation
// as a quaternion) and the shading and colour settings. Format: presets/README.md, "Animation".
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/block.hpp"
#include "core/vec.hpp"

namespace fraktal {

struct Formula;
struct Node;
struct Preset;
struct ReadContext;

enum class Interpolation { Constant, Linear, Smooth };

struct Key {
    double frame = 0.0;
    std::vector<double> value;  // 1 (a number), 3 (a vector) or 4 (an orientation quaternion w, x, y, z)
    bool operator==(const Key&) const = default;
};

// The target of an orientation track: a unit quaternion (w, x, y, z) rotating camera space (x right,
// y up, looking down -z) into world space. It sets the camera's target (at the keyed distance) and up.
inline constexpr const char* kCameraOrientationTarget = "camera.orientation";

struct Track {
    std::string target;  // a field path as in error messages, e.g. "formula.nodes[0].params.power"
    Interpolation interpolation = Interpolation::Smooth;
    std::vector<Key> keys;  // sorted by frame, at least one
    bool operator==(const Track&) const = default;
};

struct Animation {
    int firstFrame = 0;
    int lastFrame = 0;
    double fps = 24.0;
    // Camera tracks are re-timed so that the camera moves at a constant speed along its position
    // path between the position track's first and last key (the path's shape is unchanged).
    bool evenCameraSpeed = false;
    std::vector<Track> tracks;
    bool operator==(const Animation&) const = default;
    bool empty() const { return tracks.empty(); }
    int frameCount() const { return lastFrame - firstFrame + 1; }
};

// The value of `track` at `frame`: keys hold before the first and after the last one. Smooth:
// cubic Hermite with Catmull-Rom tangents over the keys' frames (C1 in time, through every key).
// Orientation tracks interpolate quaternions (linear: slerp; smooth: squad), always along the
// shorter arc, so the camera never flips.
std::vector<double> evaluateTrack(const Track& track, double frame);

// Targets of block parameters: "formula.nodes[N].params.NAME" (N counts the closing estimator
// last, as a preset file lists it) or "formula.estimator.params.NAME" (what the editor keys for
// the estimator, which stays on it when nodes are added or removed).
std::string paramTarget(size_t node, const std::string& param);
std::string estimatorParamTarget(const std::string& param);
struct ParamTarget {
    bool estimator = false;  // named as formula.estimator; else by `node`
    size_t node = 0;
    std::string name;
};
// Null for any other target (and for an index that is not a number).
std::optional<ParamTarget> parseParamTarget(const std::string& target);

// The block parameter a target keys. `node` is null for other targets and for a node that does
// not exist; `decl` is null also when the node's block has no parameter NAME.
struct KeyedParam {
    const Node* node = nullptr;
    std::string name;
    const ParamDecl* decl = nullptr;
};
KeyedParam keyedParam(const Formula& formula, const std::string& target);

// Whether the field at `target` steps from key to key in `preset`: a toggle parameter
// (ParamType::Toggle) holds the last key at or before the frame whatever its track's
// interpolation says, so it is never read between on and off.
bool stepsAtKeys(const Preset& preset, const std::string& target);
// The interpolation `track` is read with in `preset`: Constant where it steps, else the track's own.
Interpolation interpolationIn(const Preset& preset, const Track& track);

// The value of `track` at `frame` for `preset` (evaluateTrack with interpolationIn): what
// presetAtFrame writes into the preset, and so what the CPU, the GPU's uniforms and rendered
// frames see.
std::vector<double> trackValueIn(const Preset& preset, const Track& track, double frame);

// The frame (in key time) at which the camera tracks are evaluated for output frame `frame`: the
// frame itself, or when evenCameraSpeed, the key time at which the position path has covered the
// same share of its length as `frame` has of the position track's frame span.
double cameraTime(const Animation& animation, double frame);

// Unit quaternion helpers (w, x, y, z in glm::dquat).
glm::dquat orientationOf(const vec3& forward, const vec3& up);
glm::dquat slerpShortest(glm::dquat a, glm::dquat b, double t);

// The "animation" section: reads and checks it (keys sorted, values of one size per track,
// targets within the sections that can be keyed, and every key value accepted by the preset's
// own reader at that field). `still` is the rest of the preset, already read.
Animation parseAnimation(const ReadContext& context, const nlohmann::json& j, const Preset& still);
nlohmann::json animationJson(const Animation& animation);

// The still preset at `frame` (no animation section): the tracks applied to `animated`.
Preset presetAtFrame(const Preset& animated, double frame);

// Keeps block-parameter tracks on their nodes when the node list changes: old node i is now node
// newIndexOf[i], or gone (-1, and its tracks with it); newCount is the new number of nodes. A
// target that names the closing estimator by index (one past the last node, as a file lists it)
// follows the count; "formula.estimator.params.NAME" needs nothing. Other targets are untouched.
void remapNodeTracks(Animation& animation, const std::vector<int>& newIndexOf, size_t newCount);
// Drops the tracks of the closing estimator's parameters (when the estimator is replaced).
void dropEstimatorTracks(Animation& animation, size_t nodeCount);

}  // namespace fraktal
