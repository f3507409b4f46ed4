// Objects beside the fractal (core/scene_object.hpp): their distances against closed forms, the
// order of joins, intersections and carves with the estimate and its membership, their placement,
// the preset format's round trip and errors, and the editor's edits.
#include <gtest/gtest.h>

#include "app/editor/document/formula_edits.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

SceneObject objectOf(std::string_view kind, std::initializer_list<std::pair<std::string_view, vec3>> values,
                     ObjectOperation operation = ObjectOperation::Join, const vec3& center = vec3(0.0)) {
    SceneObject o = SceneObject::make(*findObject(kind));
    for (const auto& [name, v] : values)
        for (size_t i = 0; i < o.block->params.size(); ++i)
            if (o.block->params[i].name == name) o.values[i] = v;
    o.operation = operation;
    o.center = center;
    return o;
}

// A ball of radius 1 as the "fractal" (the sphere estimator on the point itself).
Formula ball() {
    Formula f;
    f.iterations = 1;
    Node sphere = Node::make(*findBlock("sphere"));
    f.estimator = sphere;
    f.boundRadius = 6.0;
    return f;
}

double boxDistance(const vec3& p, const vec3& h) {
    const vec3 q = abs(p) - h;
    return length(max(q, vec3(0.0))) + std::min(std::max(q.x, std::max(q.y, q.z)), 0.0);
}

}  // namespace

TEST(SceneObjects, EachKindIsItsClosedForm) {
    for (const vec3& p : test::randomPoints(500, 3.0, 31)) {
        EXPECT_NEAR(objectOf("sphere", {{"radius", vec3(0.7)}}).distanceAt(p), length(p) - 0.7, 1e-12);
        EXPECT_NEAR(objectOf("box", {{"size", vec3(0.5, 1.0, 0.25)}}).distanceAt(p),
                    boxDistance(p, vec3(0.5, 1.0, 0.25)), 1e-12);
        EXPECT_NEAR(objectOf("plane", {}).distanceAt(p), p.z, 1e-12);
        EXPECT_NEAR(objectOf("torus", {{"radius", vec3(1.5)}, {"tube", vec3(0.3)}}).distanceAt(p),
                    std::hypot(std::hypot(p.x, p.y) - 1.5, p.z) - 0.3, 1e-12);
        const double wall = std::hypot(p.x, p.y) - 0.8;
        EXPECT_NEAR(objectOf("cylinder", {{"radius", vec3(0.8)}, {"height", vec3(2.0)}}).distanceAt(p),
                    std::max(std::abs(p.z) - 1.0, wall), 1e-12);
        EXPECT_NEAR(
            objectOf("cylinder", {{"radius", vec3(0.8)}, {"height", vec3(2.0)}, {"caps", vec3(0.0)}}).distanceAt(p),
            std::max(std::abs(p.z) - 1.0, std::abs(wall)), 1e-12);
    }
}

// The ball, then a box joined beside it, then a sphere carved from both, then a slab that keeps
// z <= 1: each step is the union, difference and intersection of the exact distances, in order.
TEST(SceneObjects, JoinCarveAndIntersectInOrder) {
    Formula f = ball();
    f.objects = {objectOf("box", {{"size", vec3(0.5)}}, ObjectOperation::Join, vec3(1.5, 0.0, 0.0)),
                 objectOf("sphere", {{"radius", vec3(0.6)}}, ObjectOperation::Carve, vec3(0.0, 0.0, 1.0)),
                 objectOf("plane", {}, ObjectOperation::Intersect, vec3(0.0, 0.0, 0.5))};
    int inside = 0;
    for (const vec3& p : test::randomPoints(4000, 2.5, 32)) {
        double d = length(p) - 1.0;
        d = std::min(d, boxDistance(p - vec3(1.5, 0.0, 0.0), vec3(0.5)));
        d = std::max(d, -(length(p - vec3(0.0, 0.0, 1.0)) - 0.6));
        d = std::max(d, p.z - 0.5);
        const Evaluation e = evaluate(f, p);
        EXPECT_NEAR(e.distance, d, 1e-12);
        EXPECT_EQ(e.inside, d <= 0.0);
        inside += e.inside;
    }
    EXPECT_GT(inside, 100);
    // Off, an object changes nothing.
    Formula off = f;
    for (SceneObject& o : off.objects) o.enabled = false;
    EXPECT_NEAR(evaluate(off, vec3(1.5, 0.0, 0.0)).distance, 0.5, 1e-12);
    // Hollow: only the shell.
    Formula shell = ball();
    shell.objects = {objectOf("sphere", {{"radius", vec3(2.0)}}, ObjectOperation::Join, vec3(0.0))};
    shell.objects[0].hollow = true;
    EXPECT_NEAR(evaluate(shell, vec3(1.5, 0.0, 0.0)).distance, 0.5, 1e-12);
}

// An escape-time fractal keeps its membership by its orbit; an intersecting box takes away what
// lies outside it, a joined sphere adds its inside.
TEST(SceneObjects, EscapeTimeMembershipFollowsTheObjects) {
    Formula f;
    f.nodes = {Node::make(*findBlock("mandelbulb")), Node::make(*findBlock("add_c"))};
    f.estimator = Node::make(*findBlock("escape_log"));
    f.iterations = 8;
    f.bailout = 2.0;
    f.objects = {objectOf("box", {{"size", vec3(2.0, 2.0, 0.3)}}, ObjectOperation::Intersect),
                 objectOf("sphere", {{"radius", vec3(0.3)}}, ObjectOperation::Join, vec3(0.0, 0.0, 1.5))};
    Formula bare = f;
    bare.objects.clear();
    int cut = 0;
    for (const vec3& p : test::randomPoints(4000, 1.6, 33)) {
        const bool bulb = evaluate(bare, p).inside;
        const bool inBox = std::abs(p.z) <= 0.3 && std::abs(p.x) <= 2.0 && std::abs(p.y) <= 2.0;
        const bool inBall = length(p - vec3(0.0, 0.0, 1.5)) <= 0.3;
        EXPECT_EQ(evaluate(f, p).inside, (bulb && inBox) || inBall) << p.x << " " << p.y << " " << p.z;
        cut += bulb && !inBox;
    }
    EXPECT_GT(cut, 50);
}

TEST(SceneObjects, TheTurnPlacesTheObjectsFrame) {
    SceneObject bar = objectOf("box", {{"size", vec3(2.0, 0.25, 0.25)}}, ObjectOperation::Join, vec3(0.0, 0.0, 1.0));
    bar.axis = vec3(0.0, 0.0, 1.0);
    bar.angle = 90.0;  // the bar along x turned onto y
    EXPECT_LT(bar.distanceAt(vec3(0.0, 1.9, 1.0)), 0.0);
    EXPECT_GT(bar.distanceAt(vec3(1.9, 0.0, 1.0)), 1.0);
}

TEST(SceneObjects, PresetRoundTripAndClearErrors) {
    Preset p = loadPreset(test::sourceDir() / "presets/menger_objects.json");
    ASSERT_EQ(p.formula.objects.size(), 3u);
    EXPECT_EQ(p.formula.objects[1].operation, ObjectOperation::Carve);
    p.formula.objects[0].hollow = true;
    p.formula.objects[2].axis = vec3(1.0, 0.0, 0.0);
    p.formula.objects[2].angle = 25.0;
    p.formula.objects[2].enabled = false;
    const Preset back = parsePreset(serializePreset(p), "round trip");
    ASSERT_EQ(back.formula.objects.size(), 3u);
    for (size_t j = 0; j < 3; ++j) {
        const SceneObject &a = p.formula.objects[j], &b = back.formula.objects[j];
        EXPECT_EQ(a.block, b.block);
        EXPECT_EQ(a.operation, b.operation);
        EXPECT_EQ(a.hollow, b.hollow);
        EXPECT_EQ(a.enabled, b.enabled);
        EXPECT_EQ(a.center, b.center);
        EXPECT_EQ(a.axis, b.axis);
        EXPECT_EQ(a.angle, b.angle);
        EXPECT_EQ(a.values, b.values);
    }
    EXPECT_EQ(serializePreset(back), serializePreset(p));
    EXPECT_NE(back.formula.structureKey(),
              loadPreset(test::sourceDir() / "presets/menger_objects.json").formula.structureKey());

    auto errorOf = [](const std::string& objects) {
        const std::string text = R"({"format": "fraktal-preset", "version": 3, "formula": {"nodes": [{"block": "box"}],
            "objects": )" + objects +
                                 R"(}, "camera": {"position": [0, 0, 5], "target": [0, 0, 0]}})";
        try {
            parsePreset(text, "bad.json");
        } catch (const PresetError& e) {
            return e.field() + ": " + e.reason();
        }
        return std::string("no error");
    };
    EXPECT_EQ(errorOf(R"([{"object": "cone"}])").rfind("formula.objects[0].object: object 1: unknown kind 'cone'", 0),
              0u)
        << errorOf(R"([{"object": "cone"}])");
    EXPECT_NE(errorOf(R"([{"object": "box", "operation": "xor"}])").find("unknown operation \"xor\""),
              std::string::npos);
    EXPECT_NE(errorOf(R"([{"object": "sphere", "params": {"radius": -1}}])").find("object 1 'sphere'"),
              std::string::npos);
    EXPECT_NE(errorOf(R"([{"object": "sphere", "axis": [0, 0, 0]}])").find("the axis must not be zero"),
              std::string::npos);
    EXPECT_NE(errorOf(R"([{"object": "box", "size": 2}])").find("unknown field"), std::string::npos);
    std::string many = "[";
    for (int k = 0; k <= kMaxObjects; ++k) many += std::string(k ? "," : "") + R"({"object": "box"})";
    EXPECT_NE(errorOf(many + "]").find("too many objects"), std::string::npos);
}

TEST(SceneObjects, EditorAddsAndRemovesObjects) {
    Formula f = ball();
    for (int k = 0; k < kMaxObjects; ++k)
        EXPECT_TRUE(editor::addObject(f, allObjects()[size_t(k) % allObjects().size()]));
    EXPECT_FALSE(editor::addObject(f, *findObject("box")));
    EXPECT_EQ(int(f.objects.size()), kMaxObjects);
    EXPECT_TRUE(editor::removeObject(f, 0));
    EXPECT_FALSE(editor::removeObject(f, kMaxObjects));
    EXPECT_EQ(f.objects.front().block->id, allObjects()[1].id);
}

namespace {
// The plane's normal in world space: its frame's z turned by its placement.
vec3 normalOf(const SceneObject& o) { return glm::transpose(o.localFromWorld()) * vec3(0.0, 0.0, 1.0); }
}  // namespace

// Add object > Plane under the Menger sponge (its cube spans -1 .. 1 on every axis) makes a floor:
// the plane faces the camera's up (+y), its surface is just under the cube's bottom face, and the
// bound reaches far enough for the floor to fill the lower part of the default view, with the
// AO distance and fog kept the same in world units.
TEST(SceneObjects, AddedPlaneIsAFloorUnderTheFractal) {
    Preset p = loadPreset(test::sourceDir() / "presets" / "menger.json");
    const double bound = p.formula.boundRadius;
    const double aoWorld = p.shading.aoDistance * bound;
    p.shading.fogDensity = 0.5;
    const double fogWorld = p.shading.fogDensity / bound;
    ASSERT_TRUE(editor::addObject(p, *findObject("plane")));
    ASSERT_EQ(p.formula.objects.size(), 1u);
    const SceneObject& floor = p.formula.objects[0];
    EXPECT_EQ(floor.block->id, "plane");
    EXPECT_NEAR(length(normalOf(floor) - vec3(0.0, 1.0, 0.0)), 0.0, 1e-12);
    // Solid below y = -1 - a hair, empty above: the cube stands on it.
    const double surface = -floor.distanceAt(vec3(0.0));
    EXPECT_LT(surface, -1.0);
    EXPECT_GT(surface, -1.0 - 0.01 * bound);
    EXPECT_LT(floor.distanceAt(vec3(3.0, -1.05, -2.0)), 0.0);
    EXPECT_GT(floor.distanceAt(vec3(3.0, -0.99, -2.0)), 0.0);
    // The bound sphere meets the floor in a disc reaching kFloorReach camera distances out.
    const double reach = std::sqrt(p.formula.boundRadius * p.formula.boundRadius - surface * surface);
    EXPECT_GE(reach, editor::kFloorReach * length(p.camera.position));
    EXPECT_LE(p.formula.boundRadius, 100.0);
    EXPECT_NEAR(p.shading.aoDistance * p.formula.boundRadius, aoWorld, 1e-12);
    EXPECT_NEAR(p.shading.fogDensity / p.formula.boundRadius, fogWorld, 1e-12);

    // Other kinds are added as they are declared, the bound left alone.
    Preset q = loadPreset(test::sourceDir() / "presets" / "menger.json");
    ASSERT_TRUE(editor::addObject(q, *findObject("box")));
    EXPECT_EQ(q.formula.boundRadius, bound);
    EXPECT_EQ(q.formula.objects[0].center, vec3(0.0));
}

// The floor follows the camera's up, and the probe finds the lowest point along it: along z the
// cube's face at z = -1, along the diagonal of x and y its edge at -sqrt(2). A floor already there
// is no part of what the next one goes under.
TEST(SceneObjects, FloorProbeFindsTheLowestPointAlongUp) {
    Preset p = loadPreset(test::sourceDir() / "presets" / "menger.json");
    const Formula& f = p.formula;
    EXPECT_NEAR(*editor::lowestPointAlong(f, vec3(0.0, 1.0, 0.0)), -1.0, 2e-3 * f.boundRadius);
    EXPECT_NEAR(*editor::lowestPointAlong(f, vec3(0.0, 0.0, 1.0)), -1.0, 2e-3 * f.boundRadius);
    EXPECT_NEAR(*editor::lowestPointAlong(f, vec3(1.0, 1.0, 0.0)), -std::sqrt(2.0), 3e-3 * f.boundRadius);
    const SceneObject zFloor = editor::floorPlane(f, vec3(0.0, 0.0, 1.0));
    EXPECT_NEAR(length(normalOf(zFloor) - vec3(0.0, 0.0, 1.0)), 0.0, 1e-12);
    const SceneObject downFloor = editor::floorPlane(f, vec3(0.0, 0.0, -1.0));
    EXPECT_NEAR(length(normalOf(downFloor) - vec3(0.0, 0.0, -1.0)), 0.0, 1e-12);
    EXPECT_NEAR(downFloor.distanceAt(vec3(0.0)), 1.0, 0.01 * f.boundRadius);

    ASSERT_TRUE(editor::addObject(p, *findObject("plane")));
    EXPECT_NEAR(*editor::lowestPointAlong(p.formula, vec3(0.0, 1.0, 0.0)), -1.0, 2e-3 * 1.8);
    // Empty space has no lowest point: a sphere estimator pushed out of its bound.
    Formula nothing = f;
    nothing.boundRadius = 0.5;
    nothing.nodes.clear();
    nothing.estimator = Node::make(*findBlock("sphere"));
    nothing.placement.center = vec3(5.0, 0.0, 0.0);
    EXPECT_FALSE(editor::lowestPointAlong(nothing, vec3(0.0, 1.0, 0.0)));
}
