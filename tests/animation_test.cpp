// Keyframe tracks: interpolation through the keys, smoothness, even camera speed, quaternion
// orientation without flips, the "animation" section's round trip and its errors.
#include "core/animation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "core/preset.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

Track scalarTrack(Interpolation how, std::vector<std::pair<double, double>> keys) {
    Track t;
    t.target = "formula.nodes[0].params.power";
    t.interpolation = how;
    for (auto [f, v] : keys) t.keys.push_back({f, {v}});
    return t;
}

Track positionTrack(std::vector<std::pair<double, vec3>> keys) {
    Track t;
    t.target = "camera.position";
    for (auto [f, p] : keys) t.keys.push_back({f, {p.x, p.y, p.z}});
    return t;
}

vec3 asVec(const std::vector<double>& v) { return vec3(v[0], v[1], v[2]); }

const char* const kAnimatedMandelbulb = R"({
  "format": "fraktal-preset", "version": 3,
  "formula": {"nodes": [{"block": "mandelbulb", "params": {"power": 8}}, {"block": "escape_log"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "animation": {"lastFrame": 10, "fps": 30, "tracks": [
    {"target": "formula.nodes[0].params.power", "interpolation": "linear",
     "keys": [{"frame": 0, "value": 4}, {"frame": 10, "value": 9}]},
    {"target": "camera.orientation", "keys": [{"frame": 0, "value": [1, 0, 0, 0]},
                                               {"frame": 10, "value": [0.7071068, 0, 0.7071068, 0]}]},
    {"target": "camera.fovY", "interpolation": "constant", "keys": [{"frame": 0, "value": 40}, {"frame": 5, "value": 60}]}
  ]}
})";

}  // namespace

TEST(Animation, EveryInterpolationPassesThroughItsKeysAndHoldsOutside) {
    for (Interpolation how : {Interpolation::Constant, Interpolation::Linear, Interpolation::Smooth}) {
        const Track t = scalarTrack(how, {{0, 1.0}, {4, 3.0}, {10, -2.0}, {12, 5.0}});
        for (const Key& k : t.keys) EXPECT_DOUBLE_EQ(evaluateTrack(t, k.frame)[0], k.value[0]);
        EXPECT_DOUBLE_EQ(evaluateTrack(t, -5)[0], 1.0);
        EXPECT_DOUBLE_EQ(evaluateTrack(t, 50)[0], 5.0);
    }
    EXPECT_DOUBLE_EQ(evaluateTrack(scalarTrack(Interpolation::Constant, {{0, 1.0}, {4, 3.0}}), 3.99)[0], 1.0);
    EXPECT_DOUBLE_EQ(evaluateTrack(scalarTrack(Interpolation::Linear, {{0, 1.0}, {4, 3.0}}), 1.0)[0], 1.5);
}

TEST(Animation, SmoothTracksAreContinuousWithContinuousSlopeAtKeys) {
    const Track t = scalarTrack(Interpolation::Smooth, {{0, 1.0}, {3, 4.0}, {10, -2.0}, {12, 5.0}});
    const double h = 1e-5;
    for (double f : {3.0, 10.0}) {
        const double left = evaluateTrack(t, f - h)[0], at = evaluateTrack(t, f)[0], right = evaluateTrack(t, f + h)[0];
        EXPECT_NEAR(left, at, 1e-3);
        EXPECT_NEAR(right, at, 1e-3);
        const double slopeLeft = (at - left) / h, slopeRight = (right - at) / h;
        EXPECT_NEAR(slopeLeft, slopeRight, 1e-3) << "slope jumps at key " << f;
    }
    // Not linear: the curve bends between keys (a linear track would give 2.5 at frame 1.5).
    EXPECT_GT(std::abs(evaluateTrack(t, 1.5)[0] - 2.5), 1e-3);
}

TEST(Animation, EvenCameraSpeedKeepsEqualStepsAlongThePath) {
    Animation a;
    a.lastFrame = 60;
    // Keys unevenly spaced in distance: a short hop then a long leg.
    a.tracks.push_back(
        positionTrack({{0, vec3(0, 0, 5)}, {20, vec3(0.2, 0, 4.8)}, {40, vec3(3, 1, 2)}, {60, vec3(6, 0, -3)}}));
    // Distance travelled along the path from frame f to f + 1 (fine chords in key time: a chord
    // between frames would cut corners where the path turns).
    auto travelled = [&](int f) {
        const double t0 = cameraTime(a, f), t1 = cameraTime(a, f + 1);
        double d = 0.0;
        for (int s = 0; s < 50; ++s)
            d += length(asVec(evaluateTrack(a.tracks[0], t0 + (t1 - t0) * (s + 1) / 50)) -
                        asVec(evaluateTrack(a.tracks[0], t0 + (t1 - t0) * s / 50)));
        return d;
    };
    a.evenCameraSpeed = false;
    double keyedMin = 1e9, keyedMax = 0;
    for (int f = 0; f < 60; ++f) {
        keyedMin = std::min(keyedMin, travelled(f));
        keyedMax = std::max(keyedMax, travelled(f));
    }
    EXPECT_GT(keyedMax / keyedMin, 3.0) << "the keyed path should lurch, or the test shows nothing";
    a.evenCameraSpeed = true;
    double previousTime = -1, stepMin = 1e9, stepMax = 0;
    for (int f = 0; f <= 60; ++f) {
        const double t = cameraTime(a, f);
        EXPECT_GT(t, previousTime) << "camera time must increase";
        previousTime = t;
        if (f < 60) {
            stepMin = std::min(stepMin, travelled(f));
            stepMax = std::max(stepMax, travelled(f));
        }
    }
    EXPECT_LT(stepMax / stepMin, 1.02);
    EXPECT_DOUBLE_EQ(cameraTime(a, 0), 0.0);
    EXPECT_DOUBLE_EQ(cameraTime(a, 60), 60.0);
}

TEST(Animation, OrientationNeverFlips) {
    // Keys a quarter turn apart about y, one written with the opposite sign (the same rotation):
    // interpolating it as written would turn the long way round.
    Track t;
    t.target = kCameraOrientationTarget;
    const vec3 forwards[] = {vec3(0, 0, -1), vec3(-1, 0, 0), vec3(0, 0, 1), vec3(1, 0.3, 0)};
    for (int k = 0; k < 4; ++k) {
        glm::dquat q = orientationOf(forwards[k], vec3(0, 1, 0));
        if (k == 2) q = -q;
        t.keys.push_back({double(k * 10), {q.w, q.x, q.y, q.z}});
    }
    for (Interpolation how : {Interpolation::Linear, Interpolation::Smooth}) {
        t.interpolation = how;
        glm::dquat previous(1, 0, 0, 0);
        for (int step = 0; step <= 300; ++step) {
            const std::vector<double> v = evaluateTrack(t, step * 0.1);
            const glm::dquat q(v[0], v[1], v[2], v[3]);
            EXPECT_NEAR(glm::length(q), 1.0, 1e-9);
            const vec3 up = q * vec3(0, 1, 0);
            EXPECT_GT(up.y, 0.9) << "the camera rolled over at frame " << step * 0.1;
            if (step > 0) {
                const double turn = 2.0 * std::acos(std::min(1.0, std::abs(glm::dot(q, previous))));
                EXPECT_LT(turn, 0.05) << "jump at frame " << step * 0.1;
            }
            previous = q;
        }
        for (int k = 0; k < 4; ++k) {  // through every key
            const std::vector<double> v = evaluateTrack(t, k * 10.0);
            const vec3 forward = glm::dquat(v[0], v[1], v[2], v[3]) * vec3(0, 0, -1);
            EXPECT_NEAR(dot(forward, normalize(forwards[k])), 1.0, 1e-9);
        }
    }
}

TEST(Animation, PresetRoundTripsAndFramesApplyTheTracks) {
    const Preset p = parsePreset(kAnimatedMandelbulb, "anim.json");
    ASSERT_EQ(p.animation.tracks.size(), 3u);
    EXPECT_EQ(p.animation.lastFrame, 10);
    EXPECT_EQ(p.animation.fps, 30.0);
    const std::string saved = serializePreset(p);
    const Preset again = parsePreset(saved, "saved");
    EXPECT_EQ(again.animation, p.animation);
    EXPECT_EQ(serializePreset(again), saved);

    const Preset f0 = presetAtFrame(p, 0), f4 = presetAtFrame(p, 4), f10 = presetAtFrame(p, 10);
    EXPECT_TRUE(f4.animation.empty());
    EXPECT_DOUBLE_EQ(f0.formula.nodes[0].values[0].x, 4.0);
    EXPECT_DOUBLE_EQ(f4.formula.nodes[0].values[0].x, 6.0);
    EXPECT_DOUBLE_EQ(f10.formula.nodes[0].values[0].x, 9.0);
    EXPECT_EQ(f4.camera.fovY, 40.0);
    EXPECT_EQ(f10.camera.fovY, 60.0);
    // A quarter turn about y: from looking down -z to looking down -x, at the same distance.
    EXPECT_NEAR(length(f10.camera.target - f10.camera.position), 3.0, 1e-9);
    EXPECT_NEAR(dot(normalize(f10.camera.target - f10.camera.position), vec3(-1, 0, 0)), 1.0, 1e-6);
    EXPECT_NEAR(dot(normalize(f0.camera.target - f0.camera.position), vec3(0, 0, -1)), 1.0, 1e-9);
}

// A Julia-mode switch and a float of the same block, both keyed 0 at frame 0 and 1 at frame 1.
const char* const kToggleAndFloatKeyed = R"({
  "format": "fraktal-preset", "version": 3,
  "formula": {"nodes": [{"block": "mandelbulb"}, {"block": "add_c"}, {"block": "escape_log"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "animation": {"lastFrame": 3, "tracks": [
    {"target": "formula.nodes[1].params.julia", "keys": [{"frame": 0, "value": 0}, {"frame": 1, "value": 1}]},
    {"target": "formula.nodes[1].params.weight", "keys": [{"frame": 0, "value": 0}, {"frame": 1, "value": 1}]}
  ]}
})";

// A toggle holds the last key at or before the frame under every interpolation (never an
// in-between value, which its reader refuses); a float keyed the same still interpolates.
TEST(Animation, TogglesStepAtTheirKeysUnderEveryInterpolation) {
    Preset p = parsePreset(kToggleAndFloatKeyed, "toggle.json");
    const Node& addC = p.formula.nodes[1];
    const size_t julia = size_t(addC.block->paramIndex("julia")), weight = size_t(addC.block->paramIndex("weight"));
    EXPECT_TRUE(stepsAtKeys(p, "formula.nodes[1].params.julia"));
    EXPECT_FALSE(stepsAtKeys(p, "formula.nodes[1].params.weight"));
    EXPECT_FALSE(stepsAtKeys(p, "formula.nodes[0].params.power"));
    EXPECT_FALSE(stepsAtKeys(p, "formula.nodes[7].params.julia"));
    EXPECT_FALSE(stepsAtKeys(p, "camera.fovY"));
    const std::vector<double> before = {0.0, 1e-6, 0.25, 0.5, 0.75, 0.999999}, from = {1.0, 1.5, 3.0};
    for (Interpolation how : {Interpolation::Constant, Interpolation::Linear, Interpolation::Smooth}) {
        for (Track& t : p.animation.tracks) t.interpolation = how;
        const Track &toggle = p.animation.tracks[0], &number = p.animation.tracks[1];
        EXPECT_EQ(interpolationIn(p, toggle), Interpolation::Constant);
        EXPECT_EQ(interpolationIn(p, number), how);
        for (double f : before) {
            EXPECT_EQ(trackValueIn(p, toggle, f), std::vector<double>{0.0}) << int(how) << " at " << f;
            EXPECT_EQ(presetAtFrame(p, f).formula.nodes[1].values[julia].x, 0.0) << int(how) << " at " << f;
        }
        for (double f : from) {
            EXPECT_EQ(trackValueIn(p, toggle, f), std::vector<double>{1.0}) << int(how) << " at " << f;
            EXPECT_EQ(presetAtFrame(p, f).formula.nodes[1].values[julia].x, 1.0) << int(how) << " at " << f;
        }
        const double mid = presetAtFrame(p, 0.25).formula.nodes[1].values[weight].x;
        if (how == Interpolation::Constant) {
            EXPECT_EQ(mid, 0.0);
        } else {
            EXPECT_GT(mid, 0.0) << int(how);
            EXPECT_LT(mid, 1.0) << int(how);
        }
        if (how == Interpolation::Linear) {
            EXPECT_DOUBLE_EQ(presetAtFrame(p, 0.5).formula.nodes[1].values[weight].x, 0.5);
        }
    }
    // The closing estimator's toggle, which a file lists as the last node.
    const Preset e = parsePreset(R"({"format": "fraktal-preset", "version": 3,
      "formula": {"nodes": [{"block": "mandelbulb"}, {"block": "plane_combine"}]},
      "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
      "animation": {"lastFrame": 3, "tracks": [{"target": "formula.nodes[1].params.intersect",
        "keys": [{"frame": 0, "value": 0}, {"frame": 1, "value": 1}]}]}})",
                                 "estimator.json");
    const size_t intersect = size_t(e.formula.estimator.block->paramIndex("intersect"));
    EXPECT_TRUE(stepsAtKeys(e, "formula.nodes[1].params.intersect"));
    EXPECT_FALSE(stepsAtKeys(e, "formula.nodes[2].params.intersect"));
    for (double f : before) EXPECT_EQ(presetAtFrame(e, f).formula.estimator.values[intersect].x, 0.0) << f;
    for (double f : from) EXPECT_EQ(presetAtFrame(e, f).formula.estimator.values[intersect].x, 1.0) << f;
}

// Lights and the environment are keyed like any other field: a light fading in and moving, the
// environment turning; a key on a light that does not exist is the target's fault.
TEST(Animation, LightsAndEnvironmentAreKeyable) {
    const char* const lit = R"({
  "format": "fraktal-preset", "version": 3,
  "formula": {"nodes": [{"block": "mandelbulb"}, {"block": "escape_log"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "lights": [{"type": "sphere", "position": [0, 3, 0], "size": 0.2, "intensity": 2}],
  "environment": {"map": "env/sky.exr"},
  "animation": {"lastFrame": 10, "tracks": [
    {"target": "lights[0].intensity", "interpolation": "linear", "keys": [{"frame": 0, "value": 0}, {"frame": 10, "value": 5}]},
    {"target": "lights[0].position", "interpolation": "linear",
     "keys": [{"frame": 0, "value": [0, 3, 0]}, {"frame": 10, "value": [2, 3, 0]}]},
    {"target": "environment.rotation", "interpolation": "linear", "keys": [{"frame": 0, "value": 0}, {"frame": 10, "value": 90}]}
  ]}
})";
    const Preset p = parsePreset(lit, FRAKTAL_SOURCE_DIR "/presets/lit.json");
    const Preset f5 = presetAtFrame(p, 5);
    ASSERT_EQ(f5.lighting.lights.size(), 1u);
    EXPECT_DOUBLE_EQ(f5.lighting.lights[0].intensity, 2.5);
    EXPECT_NEAR(f5.lighting.lights[0].position.x, 1.0, 1e-12);
    EXPECT_DOUBLE_EQ(f5.lighting.environment.rotation, 45.0);
    EXPECT_EQ(parsePreset(serializePreset(p), FRAKTAL_SOURCE_DIR "/presets/again.json").animation, p.animation);

    std::string missing = lit;
    missing.replace(missing.find("lights[0].intensity"), 19, "lights[3].intensity");
    try {
        parsePreset(missing, FRAKTAL_SOURCE_DIR "/presets/lit.json");
        FAIL() << "a key on a missing light loaded";
    } catch (const PresetError& e) {
        EXPECT_NE(std::string(e.what()).find("lit.json"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("animation.tracks[0].target"), std::string::npos) << e.what();
    }
}

// A rect light's height is keyed like its width: it animates between its keys, a key outside the
// field's range is refused, and the track survives a save and a load.
TEST(Animation, ARectLightsHeightIsKeyable) {
    const char* const lit = R"({
  "format": "fraktal-preset", "version": 3,
  "formula": {"nodes": [{"block": "mandelbulb"}, {"block": "escape_log"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "lights": [{"type": "rect", "position": [0, 3, 0], "normal": [0, -1, 0], "up": [0, 0, 1], "size": 2, "height": 0.5}],
  "animation": {"lastFrame": 10, "tracks": [
    {"target": "lights[0].size", "interpolation": "linear", "keys": [{"frame": 0, "value": 2}, {"frame": 10, "value": 4}]},
    {"target": "lights[0].height", "interpolation": "linear", "keys": [{"frame": 0, "value": 0.5}, {"frame": 10, "value": 1.5}]}
  ]}
})";
    const Preset p = parsePreset(lit, FRAKTAL_SOURCE_DIR "/presets/rect.json");
    for (double frame : {0.0, 2.5, 5.0, 10.0}) {
        const Light l = presetAtFrame(p, frame).lighting.lights.at(0);
        EXPECT_NEAR(l.height, 0.5 + 0.1 * frame, 1e-12) << frame;
        EXPECT_NEAR(l.size, 2.0 + 0.2 * frame, 1e-12) << frame;
    }
    const Preset again = parsePreset(serializePreset(p), FRAKTAL_SOURCE_DIR "/presets/again.json");
    EXPECT_EQ(again.animation, p.animation);
    EXPECT_NEAR(presetAtFrame(again, 5.0).lighting.lights.at(0).height, 1.0, 1e-12);

    std::string negative = lit;
    const std::string lastKey = "\"value\": 1.5";
    negative.replace(negative.find(lastKey), lastKey.size(), "\"value\": -1.0");
    try {
        parsePreset(negative, FRAKTAL_SOURCE_DIR "/presets/rect.json");
        FAIL() << "a negative height key loaded";
    } catch (const PresetError& e) {
        EXPECT_NE(std::string(e.what()).find("animation.tracks[1].keys[1].value"), std::string::npos) << e.what();
    }
}

TEST(Animation, BadTracksNameFileFieldAndReason) {
    struct Case {
        const char* track;
        const char* field;
        const char* reason;
    };
    const Case cases[] = {
        {R"({"target": "formula.nodes[0].params.powr", "keys": [{"frame": 0, "value": 3}]})",
         "animation.tracks[0].target", "unknown parameter of block 'mandelbulb'"},
        {R"({"target": "formula.nodes[5].params.power", "keys": [{"frame": 0, "value": 3}]})",
         "animation.tracks[0].target", "no such field"},
        {R"({"target": "render.width", "keys": [{"frame": 0, "value": 3}]})", "animation.tracks[0].target",
         "cannot be keyed"},
        {R"({"target": "camera.position", "keys": [{"frame": 0, "value": 3}]})", "animation.tracks[0].keys[0].value",
         "expected an array of 3 numbers"},
        {R"({"target": "formula.nodes[0].params.power", "keys": [{"frame": 0, "value": 3000}]})",
         "animation.tracks[0].keys[0].value", "outside the range"},
        {R"({"target": "camera.fovY", "keys": [{"frame": 4, "value": 30}, {"frame": 2, "value": 40}]})",
         "animation.tracks[0].keys[1].frame", "increasing frame order"},
        {R"({"target": "camera.fovY", "interpolation": "cubic", "keys": [{"frame": 0, "value": 30}]})",
         "animation.tracks[0].interpolation", "expected \"constant\""},
        {R"({"target": "camera.orientation", "keys": [{"frame": 0, "value": [0, 0, 0, 0]}]})",
         "animation.tracks[0].keys[0].value", "zero quaternion"},
    };
    for (const Case& c : cases) {
        nlohmann::json j = nlohmann::json::parse(kAnimatedMandelbulb);
        j["animation"]["tracks"] = nlohmann::json::array({nlohmann::json::parse(c.track)});
        try {
            parsePreset(j.dump(), "bad_anim.json");
            ADD_FAILURE() << "accepted: " << c.track;
        } catch (const PresetError& e) {
            EXPECT_EQ(e.file(), "bad_anim.json");
            EXPECT_EQ(e.field(), c.field) << e.what();
            EXPECT_NE(e.reason().find(c.reason), std::string::npos) << e.what();
        }
    }
}

TEST(Animation, StillPresetsHaveNoAnimationSection) {
    for (const auto& path : test::shippedPresets()) {
        const Preset p = loadPreset(path);
        EXPECT_EQ(presetToJson(p).contains("animation"), p.animation != Animation{}) << path;
    }
}

// The timeline's frames per second and range, set on a document without keys, are the document's:
// a save keeps them (it wrote no animation section without tracks, and they were lost).
TEST(Animation, AFrameRateAndRangeWithoutKeysSurviveASave) {
    Preset p = loadPreset(test::shippedPresetFile("mandelbulb.json"));
    ASSERT_TRUE(p.animation.empty());
    p.animation.fps = 30.0;
    p.animation.firstFrame = 10;
    p.animation.lastFrame = 250;
    const Preset back = parsePreset(serializePreset(p), "saved.json");
    EXPECT_EQ(back.animation, p.animation);
    EXPECT_EQ(serializePreset(back), serializePreset(p));
}

// The editor keys the closing estimator's parameters as "formula.estimator.params.NAME": such a
// preset loads, saves back unchanged, and its frames set the estimator (the last node of the file),
// also after a node is added in front of it. An unknown estimator parameter is still refused.
TEST(Animation, EstimatorParameterTracksLoadAndApply) {
    const char* const keyed = R"({
  "format": "fraktal-preset", "version": 3,
  "formula": {"iterations": 1, "bailout": 100, "boundRadius": 1.8,
              "nodes": [{"block": "quaternion_julia"}]},
  "camera": {"position": [0, 0, 3], "target": [0, 0, 0]},
  "animation": {"lastFrame": 10, "tracks": [
    {"target": "formula.estimator.params.slice", "keys": [{"frame": 0, "value": -0.5}, {"frame": 10, "value": 0.5}]}
  ]}
})";
    Preset p = parsePreset(keyed, "estimator.json");
    const size_t slice = size_t(p.formula.estimator.block->paramIndex("slice"));
    EXPECT_EQ(serializePreset(parsePreset(serializePreset(p), "saved")), serializePreset(p));
    EXPECT_DOUBLE_EQ(presetAtFrame(p, 0).formula.estimator.values[slice].x, -0.5);
    EXPECT_DOUBLE_EQ(presetAtFrame(p, 5).formula.estimator.values[slice].x, 0.0);
    p.formula.nodes.insert(p.formula.nodes.begin(), Node::make(*findBlock("rotate")));
    EXPECT_DOUBLE_EQ(presetAtFrame(p, 10).formula.estimator.values[slice].x, 0.5);

    std::string unknown = keyed;
    unknown.replace(unknown.find("params.slice"), 12, "params.nope");
    try {
        parsePreset(unknown, "estimator.json");
        ADD_FAILURE() << "an unknown estimator parameter was accepted";
    } catch (const PresetError& e) {
        EXPECT_EQ(e.field(), "animation.tracks[0].target") << e.what();
    }
}
