// The editor's timeline without the UI: key edits on the document's animation and their undo
// steps, playback from the wall clock (slow frames skip animation frames), and frames evaluated
// into the document without touching the formula's blocks or the undo history.
#include "app/editor/document/timeline_edits.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "app/editor/document/undo_history.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

Document morph() {
    Document d;
    d.preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "mandelbulb_power_morph.json");
    return d;
}

const std::string kPower = "formula.nodes[0].params.power";

TEST(TimelineEdits, AddMoveDeleteKeysKeepTracksSortedAndValid) {
    Animation a;
    a.lastFrame = 100;
    EXPECT_TRUE(addKey(a, kPower, 50, {6.0}));
    EXPECT_TRUE(addKey(a, kPower, 10, {4.0}));
    EXPECT_TRUE(addKey(a, kPower, 90, {9.0}));
    ASSERT_EQ(a.tracks.size(), 1u);
    const Track& t = a.tracks[0];
    ASSERT_EQ(t.keys.size(), 3u);
    EXPECT_EQ(t.keys[0].frame, 10);
    EXPECT_EQ(t.keys[1].frame, 50);
    EXPECT_EQ(t.interpolation, Interpolation::Smooth);
    // The same frame again replaces the value; the same value changes nothing.
    EXPECT_TRUE(addKey(a, kPower, 50, {7.0}));
    EXPECT_FALSE(addKey(a, kPower, 50, {7.0}));
    EXPECT_EQ(t.keys.size(), 3u);
    EXPECT_EQ(t.keys[1].value[0], 7.0);
    // Moving past another key re-sorts; onto another key or from nowhere is refused.
    EXPECT_FALSE(moveKey(a, {kPower, 10}, 90));
    EXPECT_FALSE(moveKey(a, {kPower, 11}, 20));
    EXPECT_TRUE(moveKey(a, {kPower, 10}, 95));
    EXPECT_EQ(t.keys.back().frame, 95);
    EXPECT_EQ(t.keys.back().value[0], 4.0);
    EXPECT_EQ(evaluateTrack(t, 95)[0], 4.0);
    EXPECT_TRUE(setInterpolation(a, kPower, Interpolation::Linear));
    EXPECT_FALSE(setInterpolation(a, kPower, Interpolation::Linear));
    EXPECT_FALSE(setInterpolation(a, "camera.fovY", Interpolation::Linear));
    EXPECT_TRUE(deleteKey(a, {kPower, 50}));
    EXPECT_FALSE(deleteKey(a, {kPower, 50}));
    EXPECT_TRUE(deleteKey(a, {kPower, 90}));
    EXPECT_TRUE(deleteKey(a, {kPower, 95}));
    EXPECT_TRUE(a.tracks.empty()) << "a track without keys is removed";
}

TEST(TimelineEdits, KeyEditsRoundTripThroughThePresetFile) {
    Document d = morph();
    ASSERT_TRUE(addKey(d.preset.animation, kPower, 30, {10.5}));
    ASSERT_TRUE(addKey(d.preset.animation, "camera.fovY", 200, {30.0}));
    ASSERT_TRUE(setInterpolation(d.preset.animation, "camera.fovY", Interpolation::Constant));
    // A setting of a section the file leaves out (all at defaults) can be keyed too.
    ASSERT_TRUE(addKey(d.preset.animation, "shading.fogDensity", 0, {ShadingSettings{}.fogDensity}));
    ASSERT_TRUE(addKey(d.preset.animation, "shading.fogDensity", 100, {0.5}));
    ASSERT_EQ(presetToJson(d.preset).count("shading"), 0u);
    const Preset back = parsePreset(documentFileText(d), "saved");
    EXPECT_EQ(back.animation, d.preset.animation);
    EXPECT_EQ(evaluateTrack(*findTrack(back.animation, kPower), 30)[0], 10.5);
}

TEST(TimelineEdits, EveryKeyEditIsOneUndoStepWithItsLabel) {
    Document d = morph();
    UndoHistory h;
    h.reset(d);
    addKey(d.preset.animation, kPower, 24, {5.0});
    EXPECT_TRUE(h.commit(d));
    EXPECT_EQ(h.undoLabel(), "Add key: Mandelbulb power @ 24");
    moveKey(d.preset.animation, {kPower, 24}, 30);
    EXPECT_TRUE(h.commit(d));
    EXPECT_EQ(h.undoLabel(), "Move key: Mandelbulb power @ 24 -> 30");
    deleteKey(d.preset.animation, {kPower, 120});
    EXPECT_TRUE(h.commit(d));
    EXPECT_EQ(h.undoLabel(), "Delete key: Mandelbulb power @ 120");
    setInterpolation(d.preset.animation, "camera.position", Interpolation::Linear);
    EXPECT_TRUE(h.commit(d));
    EXPECT_EQ(h.undoLabel(), "Interpolation: camera position linear");
    addKey(d.preset.animation, "camera.fovY", 10, {50.0});
    EXPECT_TRUE(h.commit(d));
    EXPECT_EQ(h.undoLabel(), "Add key: camera fovY @ 10");
    const Animation last = d.preset.animation;
    ASSERT_TRUE(h.undo(d));
    EXPECT_FALSE(findTrack(d.preset.animation, "camera.fovY"));
    EXPECT_EQ(h.redoLabel(), "Add key: camera fovY @ 10");
    ASSERT_TRUE(h.undo(d));
    ASSERT_TRUE(h.undo(d));
    ASSERT_TRUE(h.undo(d));
    ASSERT_TRUE(h.undo(d));
    EXPECT_EQ(d.preset.animation, morph().preset.animation);
    for (int i = 0; i < 5; ++i) ASSERT_TRUE(h.redo(d));
    EXPECT_EQ(d.preset.animation, last);
}

TEST(TimelineEdits, AKeyedValueShowsAsChangedOnlyWhenItDiffers) {
    Document d = morph();
    const Animation& a = d.preset.animation;
    applyAnimationFrame(d.preset, 60);
    const Track& power = *findTrack(a, kPower);
    EXPECT_FALSE(differsFromTrack(d.preset, power, 60, {d.preset.formula.nodes[0].values[0].x}));
    EXPECT_TRUE(differsFromTrack(d.preset, power, 60, {d.preset.formula.nodes[0].values[0].x + 0.01}));
    EXPECT_TRUE(differsFromTrack(d.preset, power, 61, {d.preset.formula.nodes[0].values[0].x}));
    // An orientation keyed from the camera reads back the same, whichever sign the quaternion has.
    Preset o = d.preset;
    o.animation = Animation{};
    o.animation.lastFrame = 10;
    addKey(o.animation, kCameraOrientationTarget, 0, cameraOrientation(d.preset.camera));
    std::vector<double> flipped = cameraOrientation(d.preset.camera);
    for (double& c : flipped) c = -c;
    EXPECT_FALSE(differsFromTrack(o, o.animation.tracks[0], 5, flipped));
    Camera turned = d.preset.camera;
    turned.target += vec3(0.3, 0.0, 0.0);
    EXPECT_TRUE(differsFromTrack(o, o.animation.tracks[0], 5, cameraOrientation(turned)));
}

// A frame shown in the editor carries the keyed lights and environment into the document, as the
// render of that frame has them: a rect light's height and intensity, the environment's turn.
TEST(TimelineEdits, AFrameShowsTheKeyedLightsAndEnvironment) {
    Document d;
    d.preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "studio_mandelbulb.json");
    ASSERT_EQ(d.preset.lighting.lights.at(0).type, LightType::Rect);
    Animation& a = d.preset.animation;
    a.lastFrame = 40;
    ASSERT_TRUE(addKey(a, "lights[0].height", 0, {1.6}));
    ASSERT_TRUE(addKey(a, "lights[0].height", 40, {3.6}));
    ASSERT_TRUE(addKey(a, "lights[0].intensity", 0, {3.5}));
    ASSERT_TRUE(addKey(a, "lights[0].intensity", 40, {7.5}));
    ASSERT_TRUE(addKey(a, "environment.rotation", 0, {0.0}));
    ASSERT_TRUE(addKey(a, "environment.rotation", 40, {80.0}));
    const Lighting before = d.preset.lighting;
    applyAnimationFrame(d.preset, 20);
    const Preset expected = presetAtFrame(d.preset, 20);
    const Light& l = d.preset.lighting.lights[0];
    EXPECT_NEAR(l.height, 2.6, 1e-9);
    EXPECT_EQ(l.height, expected.lighting.lights[0].height);
    EXPECT_NEAR(l.intensity, 5.5, 1e-9);
    EXPECT_NEAR(d.preset.lighting.environment.rotation, 40.0, 1e-9);
    // What no track keys stays.
    EXPECT_EQ(l.size, before.lights[0].size);
    EXPECT_EQ(l.position, before.lights[0].position);
    EXPECT_EQ(d.preset.lighting.lights[1], before.lights[1]);
    EXPECT_EQ(d.preset.lighting.environment.map, before.environment.map);
}

// A toggle keyed off and on steps, in the document and in the key marker's check: between its keys
// it is off, and off is no change from the animation.
TEST(TimelineEdits, AKeyedToggleStepsInTheDocumentAndItsMarker) {
    Document d;
    d.preset = loadPreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "juliabulb.json");
    const std::string julia = paramTarget(1, "julia");
    Animation& a = d.preset.animation;
    addKey(a, julia, 0, {0.0});
    addKey(a, julia, 10, {1.0});
    a.lastFrame = 20;
    const Track& track = *findTrack(a, julia);
    ASSERT_EQ(track.interpolation, Interpolation::Smooth);
    const size_t index = size_t(d.preset.formula.nodes[1].block->paramIndex("julia"));
    for (int frame : {0, 3, 5, 9, 10, 15}) {
        applyAnimationFrame(d.preset, frame);
        const double on = frame < 10 ? 0.0 : 1.0;
        EXPECT_EQ(d.preset.formula.nodes[1].values[index].x, on) << frame;
        EXPECT_FALSE(differsFromTrack(d.preset, track, frame, {on})) << frame;
        EXPECT_TRUE(differsFromTrack(d.preset, track, frame, {1.0 - on})) << frame;
    }
}

TEST(TimelineEdits, PlaybackFollowsTheWallClockAndSkipsFramesWhenSlow) {
    Animation a;
    a.firstFrame = 10;
    a.lastFrame = 109;  // 100 frames
    a.fps = 24;
    EXPECT_EQ(playbackFrame(a, 10, 0.0, true).frame, 10);
    EXPECT_EQ(playbackFrame(a, 10, 1.0, true).frame, 34);
    EXPECT_EQ(playbackFrame(a, 10, 1.0 / 24 - 1e-4, true).frame, 10);
    // Frames drawn at 0.1 s then 0.6 s (a 500 ms frame): the animation jumps 12 frames, it does
    // not slow down.
    const int before = playbackFrame(a, 20, 0.1, true).frame;
    const int after = playbackFrame(a, 20, 0.6, true).frame;
    EXPECT_EQ(before, 22);
    EXPECT_EQ(after - before, 12);
    // Past the end: wraps with loop, holds the last frame and ends without.
    EXPECT_EQ(playbackFrame(a, 100, 1.0, true).frame, 10 + (124 - 10) % 100);
    const PlaybackStep end = playbackFrame(a, 100, 1.0, false);
    EXPECT_EQ(end.frame, 109);
    EXPECT_TRUE(end.ended);
    EXPECT_FALSE(playbackFrame(a, 100, 0.3, false).ended);
}

TEST(TimelineEdits, AFrameIsEvaluatedIntoTheDocumentWithoutAnUndoStep) {
    Document d = morph();
    const BlockDesc* block = d.preset.formula.nodes[0].block;
    UndoHistory h;
    h.reset(d);
    applyAnimationFrame(d.preset, 60);
    const Preset expected = presetAtFrame(morph().preset, 60);
    EXPECT_EQ(d.preset.formula.nodes[0].values, expected.formula.nodes[0].values);
    EXPECT_EQ(d.preset.camera.position, expected.camera.position);
    EXPECT_GT(d.preset.formula.nodes[0].values[0].x, 3.0);
    EXPECT_LT(d.preset.formula.nodes[0].values[0].x, 8.0);
    EXPECT_EQ(d.preset.formula.nodes[0].block, block) << "the blocks stay: no recompile";
    EXPECT_EQ(d.preset.animation, morph().preset.animation);
    h.replacePresent(d);
    EXPECT_FALSE(h.commit(d));
    EXPECT_EQ(h.undoDepth(), 0u);
}

}  // namespace
}  // namespace fraktal::editor
