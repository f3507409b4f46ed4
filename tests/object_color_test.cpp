// Objects beside the fractal take their own colour (SceneObject::color), not the fractal's
// orbit-trap palette: which surface a point is of (Evaluation::surface on the CPU, formulaEval's
// surface on the GPU), every kind's colour in GL and CPU stills and in the path tracer, a floor
// under the Menger sponge in one colour that a change of value (no recompile) changes, the preset
// format's field, and what a change of it costs and is called.
#include <gtest/gtest.h>

#include <cmath>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/undo_history.hpp"
#include "core/color/color_pipeline.hpp"
#include "core/cpu_render/cpu_path_tracer.hpp"
#include "core/cpu_render/cpu_renderer.hpp"
#include "core/gl/de_probe.hpp"
#include "core/render/path_job.hpp"
#include "core/render/path_tracer.hpp"
#include "core/render/still_renderer.hpp"
#include "core/scene/scene_revision.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

// A colour no palette of the shipped presets lands on exactly: a pixel whose albedo is this is
// the object's.
const vec3 kTeal(0.15, 0.55, 0.85);
const vec3 kRust(0.8, 0.3, 0.1);

// Whether the CPU's surface at p is the same a hair away in every direction (away from a seam
// between two surfaces, where float and double may pick either).
bool clearOfSeams(const Formula& f, const vec3& p) {
    const int surface = evaluate(f, p).surface;
    const double delta = 1e-4 * std::max(length(p), 1.0);
    for (int axis = 0; axis < 3; ++axis)
        for (double sign : {-1.0, 1.0}) {
            vec3 q = p;
            q[axis] += sign * delta;
            if (evaluate(f, q).surface != surface) return false;
        }
    return true;
}

// The Menger sponge standing on a floor (Add object > Plane, as the editor adds it) of `color`.
Preset spongeOnFloor(const vec3& color) {
    Preset p = test::shippedPreset("menger.json");
    EXPECT_TRUE(editor::addObject(p, *findObject("plane")));
    p.formula.objects.back().color = color;
    return p;
}

ImageStrip renderGL(gl::StillRenderer& renderer, const Preset& preset, const RenderSettings& r,
                    const ShadingParams& shading) {
    renderer.setScene(preset.formula, preset.camera, r, shading);
    ImageStrip image;
    image.resize(r.width, 0, r.height);
    for (const TileRect& tile : tilesOf({0, 0, r.width, r.height}, 128)) renderer.renderTile(tile, image);
    return image;
}

vec3 albedoAt(const ImageStrip& image, int x, int y) {
    const float* a = &image.albedoAO[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return vec3(a[0], a[1], a[2]);
}
vec3 colourAt(const ImageStrip& image, int x, int y) {
    const float* a = &image.rgba[(size_t(y) * size_t(image.width) + size_t(x)) * 4];
    return vec3(a[0], a[1], a[2]);
}

// Per channel, the mean and the standard deviation of `values`.
struct Spread {
    vec3 mean{0.0}, deviation{0.0};
};
Spread spreadOf(const std::vector<vec3>& values) {
    Spread s;
    for (const vec3& v : values) s.mean += v / double(values.size());
    for (const vec3& v : values) s.deviation += (v - s.mean) * (v - s.mean) / double(values.size());
    s.deviation = glm::sqrt(s.deviation);
    return s;
}

// The floor's region of an image of the sponge on its floor from menger.json's camera: the lower
// part of the image beside the sponge, left and right of it.
constexpr int kWidth = 96, kHeight = 64;
bool onTheFloor(int x, int y) {
    return y >= kHeight * 40 / 100 && y < kHeight * 95 / 100 && (x < kWidth * 12 / 100 || x >= kWidth * 88 / 100);
}

}  // namespace

// On the CPU the surface is the nearest joined object's where it is nearer than the fractal, the
// carving object's where the distance it sets is the larger, never an intersecting one's (oracles from the
// objects' own distances, every kind); the GPU names the same surface as the CPU wherever the
// point is clear of a seam between two.
TEST(ObjectColor, SurfaceIsTheObjectThatSetsTheDistanceOnCpuAndGpu) {
    Formula joined = test::shippedPreset("menger.json").formula;
    for (const ObjectDesc& kind : allObjects()) {
        SceneObject o = SceneObject::make(kind);
        o.center = vec3(1.2 * double(joined.objects.size()) - 2.4, 0.3, 0.2);
        joined.objects.push_back(o);
    }
    Formula fractalAlone = joined;
    fractalAlone.objects.clear();
    int objectPoints = 0, fractalPoints = 0;
    for (const vec3& p : test::randomPoints(4000, 2.0, 52)) {
        int expected = kFractalSurface;
        double nearest = evaluate(fractalAlone, p).distance;
        for (size_t k = 0; k < joined.objects.size(); ++k)
            if (const double d = joined.objects[k].distanceAt(p); d < nearest) {
                nearest = d;
                expected = int(k);
            }
        ASSERT_EQ(evaluate(joined, p).surface, expected) << p.x << " " << p.y << " " << p.z;
        (expected == kFractalSurface ? fractalPoints : objectPoints)++;
    }
    EXPECT_GT(objectPoints, 100);
    EXPECT_GT(fractalPoints, 100);

    // One object of each kind carving the sponge or intersecting it: the surface is a carving
    // object's where the distance it sets (-d) is above the fractal's; an intersecting one (a
    // limit box) cuts the fractal open and its faces stay the fractal's; a disabled object is
    // never the surface.
    for (const ObjectDesc& kind : allObjects())
        for (ObjectOperation operation : {ObjectOperation::Carve, ObjectOperation::Intersect}) {
            Formula cut = fractalAlone;
            SceneObject o = SceneObject::make(kind);
            o.operation = operation;
            o.center = vec3(0.2, 0.3, 0.6);
            cut.objects.push_back(o);
            int objectSide = 0, fractalSide = 0;
            for (const vec3& p : test::randomPoints(1000, 2.0, 54)) {
                const double d = evaluate(fractalAlone, p).distance;
                const double taken = operation == ObjectOperation::Carve ? -o.distanceAt(p) : o.distanceAt(p);
                const bool objectSets = taken > d;
                const int expected = objectSets && operation == ObjectOperation::Carve ? 0 : kFractalSurface;
                ASSERT_EQ(evaluate(cut, p).surface, expected) << kind.id << " " << p.x << " " << p.y << " " << p.z;
                ASSERT_EQ(evaluate(cut, p).distance, std::max(d, taken)) << kind.id;
                (objectSets ? objectSide : fractalSide)++;
            }
            EXPECT_GT(objectSide, 0) << kind.id << ": the object sets the distance nowhere: nothing tested";
            EXPECT_GT(fractalSide, 0) << kind.id;
            cut.objects[0].enabled = false;
            for (const vec3& p : test::randomPoints(100, 2.0, 55)) EXPECT_EQ(evaluate(cut, p).surface, kFractalSurface);
        }

    // On the GPU: the joined kinds and a box carving them all, so that every surface is some
    // points'.
    test::glContext();
    Formula every = joined;
    SceneObject carving = SceneObject::make(*findObject("box"));
    carving.operation = ObjectOperation::Carve;
    carving.center = vec3(1.5, 1.5, 1.5);
    every.objects.push_back(carving);
    gl::DEProbe probe(every);
    const std::vector<vec3> points = test::randomPoints(8192, 2.0, 53);
    const std::vector<gl::GpuSample> gpu = probe.evaluate(every, points);
    std::vector<int> seen(every.objects.size() + 1, 0);
    size_t compared = 0, differ = 0;
    for (size_t i = 0; i < points.size(); ++i) {
        const int cpu = evaluate(every, points[i]).surface;
        if (!clearOfSeams(every, points[i])) continue;
        ++compared;
        ++seen[size_t(cpu + 1)];
        if (gpu[i].surface != cpu) ++differ;
    }
    EXPECT_EQ(differ, 0u) << "of " << compared;
    EXPECT_GT(compared, 7000u);
    // Every surface is some points' (the fractal and each object), so each one was compared.
    for (size_t k = 0; k < seen.size(); ++k) EXPECT_GT(seen[k], 0) << "surface " << int(k) - 1;
}

// Every kind beside the sponge, in its own colour: the CPU reference's albedo is the object's
// colour on its pixels (and only the palette's elsewhere), and the GL still shows the same colour
// on the same pixels and the same image.
TEST(ObjectColor, EveryKindTakesItsColourInGlAndCpuStills) {
    test::glContext();
    for (const ObjectDesc& kind : allObjects()) {
        Preset p = test::shippedPreset("menger.json");
        ASSERT_TRUE(editor::addObject(p, kind));
        SceneObject& o = p.formula.objects.back();
        if (kind.id != "plane") {
            // Beside the sponge's corner that faces the camera, where nothing hides it.
            o.center = 1.1 * normalize(p.camera.position);
            for (size_t i = 0; i < kind.params.size(); ++i)
                if (kind.params[i].type != ParamType::Toggle) o.values[i] *= 0.6;
        }
        o.color = kTeal;
        RenderSettings r = p.render;
        r.width = kWidth;
        r.height = kHeight;
        r.spp = 1;
        const ShadingParams shading = resolveShading(p.shading, r, p.formula);
        gl::StillRenderer renderer(p.formula, 128);
        const ImageStrip gpu = renderGL(renderer, p, r, shading);
        const ImageStrip cpu = renderReference(p.formula, p.camera, r, shading);
        int objectPixels = 0, agreeing = 0;
        double squaredError = 0.0;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                const vec3 d = colourAt(gpu, x, y) - colourAt(cpu, x, y);
                squaredError += dot(d, d) / 3.0;
                if (length(albedoAt(cpu, x, y) - kTeal) > 1e-6) continue;
                ++objectPixels;
                agreeing += length(albedoAt(gpu, x, y) - kTeal) < 1e-5;
            }
        const double rms = std::sqrt(squaredError / double(kWidth * kHeight));
        std::printf("%s: %d pixels of the object, %d of them the same on GL; rms colour difference %.4f\n",
                    std::string(kind.id).c_str(), objectPixels, agreeing, rms);
        EXPECT_GT(objectPixels, kWidth * kHeight / 100) << kind.id;
        // An edge pixel's ray may hit the fractal on one and the object on the other.
        EXPECT_GE(agreeing, objectPixels * 95 / 100) << kind.id;
        EXPECT_LT(rms, 0.02) << kind.id;
    }
}

// The sponge on a floor: the floor's region is the floor's colour, the same in every pixel (the
// albedo exactly, the lit colour with the spread of its light and shadow alone); another colour
// changes it on the same program (the structure stays), in GL and CPU alike, and the path tracer's
// albedo pass is the floor's colour there too, on GL and on the CPU.
TEST(ObjectColor, FloorIsOneColourThatChangesWithoutRecompiling) {
    test::glContext();
    const Preset grey = spongeOnFloor(vec3(kDefaultObjectColor));
    const Preset rust = spongeOnFloor(kRust);
    ASSERT_EQ(grey.formula.structureKey(), rust.formula.structureKey());
    RenderSettings r = grey.render;
    r.width = kWidth;
    r.height = kHeight;
    r.spp = 1;
    gl::StillRenderer renderer(grey.formula, 128);
    // shade.glsl declares one colour for each object a formula may hold, and no more.
    auto location = [&](int k) {
        return glGetUniformLocation(renderer.program().id(), ("u_objectColors[" + std::to_string(k) + "]").c_str());
    };
    EXPECT_GE(location(kMaxObjects - 1), 0);
    EXPECT_EQ(location(kMaxObjects), -1);
    std::vector<vec3> colourShown[2];
    const Preset* scenes[] = {&grey, &rust};
    for (int s = 0; s < 2; ++s) {
        const Preset& p = *scenes[s];
        const vec3 color = p.formula.objects.back().color;
        const ShadingParams shading = resolveShading(p.shading, r, p.formula);
        const ImageStrip gpu = renderGL(renderer, p, r, shading);
        const ImageStrip cpu = renderReference(p.formula, p.camera, r, shading);
        std::vector<vec3> chroma;
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x) {
                if (!onTheFloor(x, y)) continue;
                ASSERT_LT(length(albedoAt(gpu, x, y) - color), 1e-5) << "GL, pixel " << x << ", " << y;
                ASSERT_LT(length(albedoAt(cpu, x, y) - color), 1e-6) << "CPU, pixel " << x << ", " << y;
                const vec3 c = colourAt(gpu, x, y);
                colourShown[s].push_back(c);
                chroma.push_back(c / std::max(c.x + c.y + c.z, 1e-6));
            }
        // Lit by a light and a sky of nearly the same colour everywhere: the share of each channel
        // is the floor's own, within a little; a palette's stripes move it by tenths.
        const Spread spread = spreadOf(chroma);
        const vec3 share = color / (color.x + color.y + color.z);
        std::printf("floor %.2f %.2f %.2f: channel shares %.3f %.3f %.3f (deviation %.4f %.4f %.4f)\n", color.x,
                    color.y, color.z, spread.mean.x, spread.mean.y, spread.mean.z, spread.deviation.x,
                    spread.deviation.y, spread.deviation.z);
        for (int c = 0; c < 3; ++c) {
            EXPECT_LT(spread.deviation[c], 0.03) << "channel " << c;
            EXPECT_NEAR(spread.mean[c], share[c], 0.08) << "channel " << c;
        }
    }
    // Rust is redder and less blue than grey in every pixel of the floor's region.
    int redder = 0;
    for (size_t i = 0; i < colourShown[0].size(); ++i)
        redder += colourShown[1][i].x / colourShown[1][i].z > 1.5 * colourShown[0][i].x / colourShown[0][i].z;
    EXPECT_EQ(redder, int(colourShown[0].size()));

    // The path tracer: the albedo pass of the floor's pixels is the floor's colour, on GL and CPU.
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    RenderSettings small = rust.render;
    small.width = kWidth / 2;
    small.height = kHeight / 2;
    const PathSceneData data = resolvePathScene(rust, "", color);
    gl::PathTracer tracer(rust.formula, small.width, small.height);
    tracer.setScene(data.scene(rust, small));
    tracer.addSamples(2);
    const PathImage gpu = tracer.image();
    const PathImage cpu = pathTraceReference(data.scene(rust, small), 0, 2);
    const vec3 working = data.shading.objectColors[0];
    for (int y = 0; y < small.height; ++y)
        for (int x = 0; x < small.width; ++x)
            for (int c = 0; c < 3 && onTheFloor(2 * x, 2 * y); ++c) {
                EXPECT_NEAR(gpu.at(kAlbedo, x, y)[c], working[c], 1e-5) << "GL, pixel " << x << ", " << y;
                EXPECT_NEAR(cpu.at(kAlbedo, x, y)[c], working[c], 1e-6) << "CPU, pixel " << x << ", " << y;
            }
}

// The colour is taken into the working space with the scene's other colours: in ACEScg the
// resolved colour is the converted one, as the light's is.
TEST(ObjectColor, ResolvedInTheWorkingSpaceLikeTheLight) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    Preset p = spongeOnFloor(kRust);
    p.render.workingSpace = "ACEScg";
    const std::string space = color.resolveSpace(p.render.workingSpace);
    const auto toWorking = [&](const vec3& c) { return color.fromLinearRec709(c, space); };
    const ShadingParams shading = resolveShading(p.shading, p.render, p.formula, toWorking);
    const vec3 expected = color.fromLinearRec709(kRust, space);
    EXPECT_LT(length(shading.objectColors[0] - expected), 1e-9);
    EXPECT_GT(length(expected - kRust), 0.01);  // ACEScg is not Rec.709: the conversion did something
}

// The preset field: written where it is not the default, read back exactly; a preset without it
// (every preset written before objects had a colour) reads the default grey; a value of the wrong
// type or out of range is refused naming the file and the field.
TEST(ObjectColor, PresetFieldRoundTripsAndRefusesBadValues) {
    Preset p = spongeOnFloor(vec3(0.123456789, 0.5, 1.0));
    p.formula.objects.push_back(SceneObject::make(*findObject("sphere")));
    const std::string text = serializePreset(p);
    const Preset back = parsePreset(text, "round trip");
    ASSERT_EQ(back.formula.objects.size(), 2u);
    EXPECT_EQ(back.formula.objects[0].color, p.formula.objects[0].color);
    EXPECT_EQ(back.formula.objects[1].color, vec3(kDefaultObjectColor));
    EXPECT_EQ(serializePreset(back), text);
    const nlohmann::json written = nlohmann::json::parse(text);
    EXPECT_TRUE(written["formula"]["objects"][0].contains("color"));
    EXPECT_FALSE(written["formula"]["objects"][1].contains("color")) << "the default is not written";

    auto withObject = [](const std::string& object) {
        return R"({"format": "fraktal-preset", "version": 3, "formula": {"nodes": [{"block": "box"}],
            "objects": [)" +
               object + R"(]}, "camera": {"position": [0, 0, 5], "target": [0, 0, 0]}})";
    };
    const Preset old = parsePreset(withObject(R"({"object": "plane"})"), "old.json");
    EXPECT_EQ(old.formula.objects[0].color, vec3(kDefaultObjectColor));

    auto errorOf = [&](const std::string& object) {
        try {
            parsePreset(withObject(object), "bad.json");
        } catch (const PresetError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    for (const char* bad :
         {R"({"object": "plane", "color": "grey"})", R"({"object": "plane", "color": [1, 0]})",
          R"({"object": "plane", "color": [1.5, 0, 0]})", R"({"object": "plane", "color": [0, -0.1, 0]})"}) {
        const std::string error = errorOf(bad);
        EXPECT_NE(error.find("bad.json"), std::string::npos) << bad << ": " << error;
        EXPECT_NE(error.find("formula.objects[0].color"), std::string::npos) << bad << ": " << error;
    }
    EXPECT_NE(errorOf(R"({"object": "plane", "color": [1.5, 0, 0]})").find("range"), std::string::npos)
        << errorOf(R"({"object": "plane", "color": [1.5, 0, 0]})");
}

// A change of an object's colour restarts the accumulation and recompiles nothing; its undo step
// is named in the artist's words.
TEST(ObjectColor, ChangeRestartsWithoutRecompileAndNamesItsUndo) {
    const Preset grey = spongeOnFloor(vec3(kDefaultObjectColor));
    const Preset rust = spongeOnFloor(kRust);
    const scene::SceneRevision a = scene::sceneRevision(grey), b = scene::sceneRevision(rust);
    const scene::SceneChange change = scene::sceneChange(&a, b);
    EXPECT_FALSE(change.structure);
    EXPECT_TRUE(change.values);
    EXPECT_FALSE(change.camera);
    editor::Document before, after;
    before.preset = grey;
    after.preset = rust;
    EXPECT_EQ(editor::describeChange(before, after), "change of colour");
}
