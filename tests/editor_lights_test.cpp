// The Lights tab's logic (app/editor/document/lights_edits.hpp): the light list's edits within kMaxLights,
// the environment map check, the focus distance of the surface under the cursor, the undo
// label of a light list edit and the viewport click that picks the focus.
// GLFW only for its key and button codes: no GL header of its own before epoxy's (the unity
// build batches this file with tests that include epoxy).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "app/editor/document/lights_edits.hpp"
#include "app/editor/document/undo_history.hpp"
#include "app/editor/input/pointer_input.hpp"
#include "core/image/environment.hpp"
#include "core/preset.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

Preset mandelbulb() { return loadPreset(test::sourceDir() / "presets" / "mandelbulb.json"); }

TEST(LightsEdits, AddFillsToTheLimitThenRefusesWithAMessage) {
    Lighting l;
    for (int i = 0; i < kMaxLights; ++i) {
        const LightType type = i % 3 == 0 ? LightType::Directional : i % 3 == 1 ? LightType::Sphere : LightType::Rect;
        EXPECT_EQ(addLight(l, type), "") << "light " << i;
        ASSERT_EQ(l.lights.size(), size_t(i + 1));
        EXPECT_EQ(l.lights.back().type, type);
    }
    const Lighting full = l;
    const std::string refused = addLight(l, LightType::Sphere);
    EXPECT_NE(refused.find(std::to_string(kMaxLights)), std::string::npos) << refused;
    EXPECT_EQ(l, full);
    EXPECT_NE(duplicateLight(l, 0), "");
    EXPECT_EQ(l, full);
}

TEST(LightsEdits, NewLightsAreValidPresetLights) {
    // Every new light must survive a save and reload (the reader checks sizes, rect frames).
    Preset p = mandelbulb();
    for (LightType type : {LightType::Directional, LightType::Sphere, LightType::Rect})
        ASSERT_EQ(addLight(p.lighting, type), "");
    const Preset back = parsePreset(presetToJson(p).dump(), "new_lights.json");
    EXPECT_EQ(back.lighting.lights, p.lighting.lights);
    for (const Light& light : p.lighting.lights) {
        EXPECT_GE(light.size, 0.0);
        EXPECT_GT(light.intensity, 0.0);
        EXPECT_TRUE(light.enabled);
    }
}

TEST(LightsEdits, DuplicateInsertsACopyAfterAndRemoveTakesTheIndex) {
    Lighting l;
    addLight(l, LightType::Directional);
    addLight(l, LightType::Sphere);
    l.lights[0].intensity = 3.5;
    EXPECT_EQ(duplicateLight(l, 0), "");
    ASSERT_EQ(l.lights.size(), 3u);
    EXPECT_EQ(l.lights[1], l.lights[0]);
    EXPECT_EQ(l.lights[2].type, LightType::Sphere);
    EXPECT_NE(duplicateLight(l, 3), "");
    EXPECT_NE(duplicateLight(l, -1), "");
    EXPECT_EQ(l.lights.size(), 3u);

    EXPECT_TRUE(removeLight(l, 1));
    ASSERT_EQ(l.lights.size(), 2u);
    EXPECT_EQ(l.lights[0].intensity, 3.5);
    EXPECT_EQ(l.lights[1].type, LightType::Sphere);
    EXPECT_FALSE(removeLight(l, 2));
    EXPECT_FALSE(removeLight(l, -1));
    EXPECT_EQ(l.lights.size(), 2u);
}

TEST(LightsEdits, UndoLabelNamesTheLightAddedOrRemoved) {
    Document a;
    a.preset = mandelbulb();
    Document b = a;
    addLight(b.preset.lighting, LightType::Rect);
    EXPECT_EQ(describeChange(a, b), "add Rect light");
    EXPECT_EQ(describeChange(b, a), "remove Rect light");
    Document c = b;
    c.preset.lighting.lights[0].intensity = 7.0;
    EXPECT_EQ(describeChange(b, c), "change of intensity");
}

TEST(LightsEdits, EnvironmentMapProblemsAreNamed) {
    const fs::path dir = fs::temp_directory_path() / "fraktal_lights_test";
    fs::create_directories(dir);
    const fs::path sky = test::sourceDir() / "presets" / "env" / "sky.exr";
    EXPECT_EQ(environmentMapProblem(sky), "");

    EXPECT_NE(environmentMapProblem(dir / "missing.exr").find("does not exist"), std::string::npos);
    EXPECT_NE(environmentMapProblem(dir).find("not a file"), std::string::npos);
    std::ofstream(dir / "fake.exr") << "not an image";
    EXPECT_NE(environmentMapProblem(dir / "fake.exr").find("not an OpenEXR"), std::string::npos);
    fs::copy_file(sky, dir / "sky.png", fs::copy_options::overwrite_existing);
    EXPECT_NE(environmentMapProblem(dir / "sky.png").find(".exr"), std::string::npos);
    fs::remove_all(dir);
}

TEST(LightsEdits, EnvironmentMapValueIsRelativeToThePresetFolder) {
    EXPECT_EQ(environmentMapValue("/a/presets/env/sky.exr", "/a/presets/scene.json"), "env/sky.exr");
    EXPECT_EQ(environmentMapValue("/a/maps/sky.exr", "/a/presets/scene.json"), "../maps/sky.exr");
    EXPECT_EQ(environmentMapValue("/a/maps/sky.exr", ""), "/a/maps/sky.exr");
    // And the renderer resolves each value back to the chosen file.
    for (const char* file : {"/a/presets/env/sky.exr", "/a/maps/sky.exr"})
        EXPECT_EQ(resolveEnvironmentPath(environmentMapValue(file, "/a/presets/scene.json"), "/a/presets/scene.json")
                      .lexically_normal(),
                  fs::path(file));
}

TEST(LightsFocus, ViewAxisDistanceIsTheDepthNotTheRayLength) {
    Camera c;
    c.position = vec3(0.0, 0.0, 4.0);
    c.target = vec3(0.0);
    EXPECT_DOUBLE_EQ(viewAxisDistance(c, vec3(0.0, 0.0, 1.0)), 3.0);
    // Off the axis: the ray is longer, the depth the same.
    const vec3 off(1.0, 0.5, 1.0);
    EXPECT_NEAR(viewAxisDistance(c, off), 3.0, 1e-12);
    EXPECT_GT(length(off - c.position), 3.1);
    // A camera looking along a diagonal.
    c.position = vec3(2.0, 2.0, 2.0);
    EXPECT_NEAR(viewAxisDistance(c, vec3(0.0)), std::sqrt(12.0), 1e-12);
    EXPECT_NEAR(viewAxisDistance(c, vec3(1.0, -1.0, 0.0)), std::sqrt(12.0), 1e-12);  // in the plane through 0
}

// A unit cube (the box estimator with no folds) seen straight on its +z face from z = 4.
Preset cubePreset() {
    return parsePreset(R"({"format": "fraktal-preset", "version": 3,
        "formula": {"iterations": 1, "bailout": 1000, "boundRadius": 2.0,
                    "nodes": [{"block": "box", "params": {"size": [1.0, 1.0, 1.0]}}]},
        "camera": {"position": [0.0, 0.0, 4.0], "target": [0.0, 0.0, 0.0], "fovY": 40.0}})",
                       "cube.json");
}

std::optional<vec3> pick(const Preset& p, double ndcX, double ndcY) {
    return surfaceUnderCursor(p.formula, p.camera, p.render, p.shading, cpuDistance(p.formula), ndcX, ndcY, 1.5, 600.0);
}

TEST(LightsFocus, SurfaceUnderTheCursorIsTheMarchedHit) {
    const Preset p = cubePreset();
    ASSERT_TRUE(p.formula.cpuEvaluable());
    const auto centre = pick(p, 0.0, 0.0);
    ASSERT_TRUE(centre.has_value());
    EXPECT_NEAR(centre->z, 1.0, 0.01);
    EXPECT_NEAR(viewAxisDistance(p.camera, *centre), 3.0, 0.01);
    // Near the face's corner the ray is ~6 % longer than the depth; the depth stays 3.
    const double tanHalf = std::tan(20.0 * 3.14159265358979 / 180.0);
    const double ndc = 0.9 / (3.0 * tanHalf);  // x = y = 0.9 on the face
    const auto corner = pick(p, ndc / 1.5, ndc);
    ASSERT_TRUE(corner.has_value());
    EXPECT_NEAR(corner->x, 0.9, 0.01);
    EXPECT_NEAR(viewAxisDistance(p.camera, *corner), 3.0, 0.01);
    EXPECT_GT(length(*corner - p.camera.position), 3.15);
    // Past the cube's silhouette: the sky.
    EXPECT_FALSE(pick(p, 0.98, 0.98).has_value());
    EXPECT_FALSE(pick(p, -0.98, 0.0).has_value());
}

TEST(LightsFocus, SphereTracingFallbackAgreesWithTheMarcher) {
    // The fallback for formulas with custom GLSL, given the cube's exact distance (Quilez, "distance
    // functions"), finds the face where the CPU marcher does; it stops at the pixel footprint.
    const DistanceAt box = [](const vec3& q) {
        const vec3 d = glm::abs(q) - vec3(1.0);
        return length(glm::max(d, vec3(0.0))) + std::min(std::max(d.x, std::max(d.y, d.z)), 0.0);
    };
    const Preset p = cubePreset();
    const auto marched = pick(p, 0.2, -0.1);
    ASSERT_TRUE(marched.has_value());
    const vec3 ro = p.camera.position, rd = p.camera.rayDirection(0.2, -0.1, 1.5);
    const double pixelAngle = p.camera.pixelAngle(600.0);
    cpu::MarchRule rule;
    rule.coneAngle = pixelAngle * 0.5;
    const auto t = traceDistance(box, ro, rd, 0.0, 10.0, rule, 256);
    ASSERT_TRUE(t.has_value());
    EXPECT_NEAR(length(*marched - ro), *t, 0.01);
    EXPECT_LT(box(ro + rd * *t), pixelAngle * *t * 0.5);
    // A ray past the cube, and one stopped short by tEnd, find nothing.
    EXPECT_FALSE(traceDistance(box, ro, vec3(0.0, 1.0, 0.0), 0.0, 10.0, rule, 256).has_value());
    EXPECT_FALSE(traceDistance(box, ro, vec3(0.0, 0.0, -1.0), 0.0, 2.5, rule, 256).has_value());
}

TEST(LightsFocus, ClickWithCtrlIsReportedWithItsModifiers) {
    ViewportDrag drag;
    const ViewportRect rect{100, 50, 800, 600};
    std::vector<PointerEvent> events = {{PointerEvent::Kind::Press, 0, 400, 300, GLFW_MOD_CONTROL},
                                        {PointerEvent::Kind::Move, 0, 402, 301, GLFW_MOD_CONTROL},
                                        {PointerEvent::Kind::Release, 0, 402, 301, GLFW_MOD_CONTROL}};
    DragMotion m = consumePointerEvents(drag, events, rect, false);
    ASSERT_EQ(m.clicks.size(), 1u);
    EXPECT_EQ(m.clicks[0].button, 0);
    EXPECT_EQ(m.clicks[0].mods & GLFW_MOD_CONTROL, GLFW_MOD_CONTROL);
    EXPECT_EQ(m.clicks[0].at, vec2(400, 300));
    EXPECT_EQ(m.rotate, vec2(0.0));
    // A drag is no click; nor is a press on a panel (the UI owns the mouse).
    events = {{PointerEvent::Kind::Press, 0, 400, 300, 0},
              {PointerEvent::Kind::Move, 0, 440, 300, 0},
              {PointerEvent::Kind::Release, 0, 440, 300, 0}};
    m = consumePointerEvents(drag, events, rect, false);
    EXPECT_TRUE(m.clicks.empty());
    EXPECT_NE(m.rotate, vec2(0.0));
    events = {{PointerEvent::Kind::Press, 0, 400, 300, 0}, {PointerEvent::Kind::Release, 0, 400, 300, 0}};
    EXPECT_TRUE(consumePointerEvents(drag, events, rect, true).clicks.empty());
    EXPECT_EQ(consumePointerEvents(drag, events, rect, false).clicks.size(), 1u);
}

}  // namespace
}  // namespace fraktal::editor
