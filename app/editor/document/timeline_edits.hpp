// The editor's animation timeline without the UI: key edits on a preset's animation (add, delete,
// move, interpolation), the words an undo step uses for them, playback from the wall clock, and
// the animation evaluated into the document at a frame. The timeline panel
// (timeline_panel.cpp) and the key markers beside the parameter widgets draw from this.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "core/preset.hpp"

namespace fraktal::editor {

// A key of the timeline: the track's target and the key's frame.
struct KeyRef {
    std::string target;
    double frame = 0.0;
    bool operator==(const KeyRef&) const = default;
};

// What the timeline shows and does; not part of the document (scrubbing and playing are no
// edits, like moving the camera). The frame range, fps and keys are the document's animation.
struct TimelineState {
    int frame = 0;
    bool playing = false;
    bool loop = true;
    double playStartTime = 0.0;  // wall clock (s) and frame at which playback (re)started
    int playStartFrame = 0;
    bool showCameraPath = false;     // View > Camera path
    std::optional<KeyRef> selected;  // the key Delete removes
    std::optional<KeyRef> dragged;   // a key being dragged along the timeline (moved on release)
    double dragFrame = 0.0;          // where the dragged key would land
    bool hovered = false;            // the timeline panel was hovered last frame (Space, Delete)
    float height = 0.0f;             // the panel's height, taken from the viewport
    int firstRow = 0;                // the first track shown when there are more than fit (mouse wheel)
    // The frame and animation last written into the document: another frame, or an edit of the
    // animation (a key added, undo), evaluates the animation again.
    std::optional<int> appliedFrame;
    Animation appliedAnimation;
    // Where the panel drew its controls this frame, in window pixels, for the state file that
    // tests driving the editor read: the scrub bar (x, y, w, h), the play and camera-path buttons'
    // centres, each key marker's centre by target.
    float bar[4] = {0, 0, 0, 0};  // frame f is at x = bar[0] + (f - shownFirst) / (shownLast - shownFirst) * bar[2]
    int shownFirst = 0, shownLast = 0;
    float playButton[2] = {0, 0};
    float pathButton[2] = {0, 0};
    std::vector<std::pair<std::string, std::pair<float, float>>> keyMarkers;
};

// The last frame the timeline shows: the animation's, or for a still (no tracks, one frame) a
// default span of 240 frames, the range a first key extends the animation to.
inline constexpr int kDefaultTimelineSpan = 240;
int shownLastFrame(const Animation& a);

// The timeline's state and controls' positions for the editor's state file.
nlohmann::json timelineJson(const TimelineState& t);

const Track* findTrack(const Animation& a, const std::string& target);
// The key of `track` at `frame` (keys sit on whole frames in the editor), or nullptr.
const Key* keyAt(const Track& track, double frame);

// Whether `value` differs from what `track` of `p`'s animation gives at `frame` (camera tracks at
// the camera's time, cameraTime; a toggle steps, trackValueIn): a keyed value the user edited since
// the frame was shown.
bool differsFromTrack(const Preset& p, const Track& track, double frame, const std::vector<double>& value);
// The camera's orientation as an orientation track keys it (w, x, y, z).
std::vector<double> cameraOrientation(const Camera& c);

// Key edits; each returns whether the animation changed. A new track interpolates smoothly.
// Adding where a key is replaces its value.
bool addKey(Animation& a, const std::string& target, double frame, std::vector<double> value);
// Removes the key; a track left without keys is removed.
bool deleteKey(Animation& a, const KeyRef& key);
// Refused (false) when there is no such key or another key is at `toFrame`.
bool moveKey(Animation& a, const KeyRef& key, double toFrame);
bool setInterpolation(Animation& a, const std::string& target, Interpolation interpolation);

// What a person calls a target: "Mandelbulb power" (block label and parameter), "camera
// position", "shading fogDensity".
std::string targetLabel(const Preset& p, const std::string& target);
// The undo step's words for an edit of the animation, such as "Add key: Mandelbulb power @ 24";
// empty when the two animations are the same.
std::string describeAnimationChange(const Preset& before, const Preset& after);

// Playback by the wall clock: the frame `elapsed` seconds after starting at `startFrame`, at the
// animation's fps. A slow frame skips animation frames rather than slowing time. Past the last
// frame it wraps to the first (loop) or holds the last and says it ended.
struct PlaybackStep {
    int frame = 0;
    bool ended = false;
};
PlaybackStep playbackFrame(const Animation& a, int startFrame, double elapsed, bool loop);

// Writes the animation's values at `frame` into the preset's still fields (formula values,
// camera, shading, colour settings, lights, environment, lens), leaving the animation and the
// formula's structure (its blocks) as they are, so the viewport updates uniforms and recompiles
// nothing.
void applyAnimationFrame(Preset& p, double frame);

}  // namespace fraktal::editor
