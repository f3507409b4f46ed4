// Print-quality light: the preset's lights/environment/lens sections (round trips, bad input), the
// environment map's importance sampling, the GL path tracer against the CPU reference, and the
// thin lens's depth of field against the circle of confusion.
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <functional>

#include "core/color/color_pipeline.hpp"
#include "core/cpu_render/cpu_path_tracer.hpp"
#include "core/image/environment.hpp"
#include "core/random_vec.hpp"
#include "core/render/path_tracer.hpp"
#include "core/render/still_renderer.hpp"
#include "core/viewport/converge.hpp"
#include "core/viewport/viewport.hpp"
#include "test_support.hpp"
#include "uniform_lookups.hpp"

namespace fraktal {
namespace {

const char* kLitPreset = R"({
  "format": "fraktal-preset", "version": 2,
  "formula": {"iterations": 0, "boundRadius": 3, "nodes": [{"block": "sphere", "params": {"radius": 1}}]},
  "camera": {"position": [0, 0.5, 4], "target": [0, 0, 0], "fovY": 40, "aperture": 0.05, "focusDistance": 3.5, "blades": 6},
  "lights": [
    {"type": "directional", "direction": [0.3, 1, 0.2], "color": [1, 0.9, 0.8], "intensity": 2, "size": 0.5},
    {"type": "sphere", "position": [2, 2, 2], "intensity": 20, "size": 0.3},
    {"type": "point", "position": [-2, 1, 2], "intensity": 5, "enabled": false},
    {"type": "rect", "position": [0, 2.5, 0], "normal": [0, -1, 0], "up": [0, 0, 1], "size": 1.5, "height": 0.5, "intensity": 4}
  ],
  "environment": {"map": "env/sky.exr", "intensity": 0.5, "rotation": 30, "visible": false},
  "pathTrace": {"bounces": 2, "roughness": 0.5, "specular": 0.1, "emission": 0.2}
})";

std::string presetPath() { return (test::sourceDir() / "presets" / "lit.json").string(); }

std::string expectError(const std::string& text, const std::string& field) {
    try {
        parsePreset(text, "bad.json");
    } catch (const PresetError& e) {
        EXPECT_EQ(e.field(), field) << e.what();
        EXPECT_EQ(e.file(), "bad.json");
        return e.reason();
    }
    ADD_FAILURE() << "no error for " << field;
    return "";
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return text.replace(at, from.size(), to);
}

TEST(LightingPreset, RoundTripsEveryField) {
    const Preset p = parsePreset(kLitPreset, presetPath());
    ASSERT_EQ(p.lighting.lights.size(), 4u);
    EXPECT_EQ(p.lighting.lights[0].type, LightType::Directional);
    EXPECT_EQ(p.lighting.lights[1].type, LightType::Sphere);
    EXPECT_EQ(p.lighting.lights[2].type, LightType::Sphere);
    EXPECT_FALSE(p.lighting.lights[2].enabled);
    EXPECT_EQ(p.lighting.lights[3].type, LightType::Rect);
    EXPECT_DOUBLE_EQ(p.lighting.lights[3].height, 0.5);
    EXPECT_DOUBLE_EQ(p.lighting.lens.apertureRadius, 0.05);
    EXPECT_EQ(p.lighting.lens.blades, 6);
    EXPECT_EQ(p.lighting.environment.map, "env/sky.exr");
    EXPECT_FALSE(p.lighting.environment.visible);
    EXPECT_EQ(p.lighting.pathTrace.bounces, 2);
    const Preset again = parsePreset(serializePreset(p), presetPath());
    EXPECT_EQ(again.lighting, p.lighting);
    EXPECT_EQ(serializePreset(again), serializePreset(p));
}

// One table names the light types: presets write its name ("point" reads as a sphere and is
// written "sphere"), the editor shows its label.
TEST(LightingPreset, TypeNamesComeFromOneTable) {
    const Preset p = parsePreset(kLitPreset, presetPath());
    const nlohmann::json lights = presetToJson(p)["lights"];
    ASSERT_EQ(lights.size(), 4u);
    EXPECT_EQ(lights[0]["type"], "directional");
    EXPECT_EQ(lights[1]["type"], "sphere");
    EXPECT_EQ(lights[2]["type"], "sphere");
    EXPECT_EQ(lights[3]["type"], "rect");
    for (const LightTypeNames& n : kLightTypeNames) {
        EXPECT_EQ(&lightTypeNames(n.type), &n);
        for (const char* name : {n.name, n.alias}) {
            if (!name) continue;
            const Preset one = parsePreset(R"({"format": "fraktal-preset", "version": 3,
                "formula": {"iterations": 0, "nodes": [{"block": "sphere"}]}, "camera": {"position": [0, 0, 4], "target": [0, 0, 0]},
                "lights": [{"type": ")" + std::string(name) +
                                               R"("}]})",
                                           presetPath());
            ASSERT_EQ(one.lighting.lights.size(), 1u);
            EXPECT_EQ(one.lighting.lights[0].type, n.type) << name;
            EXPECT_EQ(presetToJson(one)["lights"][0]["type"], n.name) << name;
        }
    }
    EXPECT_STREQ(lightTypeNames(LightType::Directional).label, "Directional");
    EXPECT_STREQ(lightTypeNames(LightType::Sphere).label, "Sphere");
    EXPECT_STREQ(lightTypeNames(LightType::Rect).label, "Rect");
}

TEST(LightingPreset, FastModeSaysWhatItLeavesOut) {
    Lighting lighting;
    EXPECT_EQ(lightingIgnoredByFastMode(lighting), "");
    lighting.lights.resize(2);
    lighting.lights[1].enabled = false;
    EXPECT_NE(lightingIgnoredByFastMode(lighting).find("the preset's 1 light applies only with --mode path"),
              std::string::npos)
        << lightingIgnoredByFastMode(lighting);
    lighting.lights[1].enabled = true;
    lighting.environment.map = "env/sky.exr";
    lighting.lens.apertureRadius = 0.01;
    // The fast renderer has the lens (shaders/lens.glsl): its depth of field is not listed.
    EXPECT_NE(lightingIgnoredByFastMode(lighting).find(
                  "the preset's 2 lights and the environment map apply only with --mode path"),
              std::string::npos)
        << lightingIgnoredByFastMode(lighting);
}

TEST(LightingPreset, FStopGivesTheThinLensRadius) {
    const Preset p = parsePreset(replaced(kLitPreset, "\"aperture\": 0.05", "\"fStop\": 2"), "f.json");
    // f = (0.024 / 2) / tan(20 deg); radius = f / (2 N).
    EXPECT_NEAR(p.lighting.lens.apertureRadius, 0.012 / std::tan(20.0 * M_PI / 180.0) / 4.0, 1e-12);
}

// A preset without lighting gains none on save; one with it (the showcases) keeps it exactly.
TEST(LightingPreset, ShippedPresetsSaveTheirLightingUnchanged) {
    const char* const keys[] = {"\"lights\"", "\"environment\"", "\"pathTrace\"", "\"aperture\""};
    int lit = 0;
    for (const auto& path : test::shippedPresets()) {
        std::ifstream in(path);
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        const bool hasLighting = std::any_of(std::begin(keys), std::end(keys),
                                             [&](const char* k) { return text.find(k) != std::string::npos; });
        const Preset p = loadPreset(path);
        const std::string saved = serializePreset(p);
        if (!hasLighting) {
            EXPECT_EQ(p.lighting, Lighting{}) << path;
            for (const char* key : keys) EXPECT_EQ(saved.find(key), std::string::npos) << path << " " << key;
            continue;
        }
        ++lit;
        EXPECT_NE(p.lighting, Lighting{}) << path;
        EXPECT_EQ(parsePreset(saved, path.string()).lighting, p.lighting) << path;
    }
    EXPECT_GE(lit, 4) << "the showcase presets (README.md, Gallery) carry lights, a lens or an environment";
}

TEST(LightingPreset, BadInputNamesFileFieldAndReason) {
    EXPECT_NE(expectError(replaced(kLitPreset, "\"size\": 0.3", "\"size\": -0.3"), "lights[1].size").find("negative"),
              std::string::npos);
    EXPECT_NE(expectError(replaced(kLitPreset, "env/sky.exr", "env/sky.png"), "environment.map").find("OpenEXR"),
              std::string::npos);
    EXPECT_NE(expectError(replaced(kLitPreset, "\"aperture\": 0.05", "\"aperture\": 0"), "camera.aperture")
                  .find("no depth of field"),
              std::string::npos);
    EXPECT_EQ(expectError(replaced(kLitPreset, "\"type\": \"rect\"", "\"type\": \"spot\""), "lights[3].type"),
              "unknown light type 'spot' (known: directional, sphere, point, rect)");
    expectError(replaced(kLitPreset, "\"bounces\": 2", "\"bounces\": 99"), "pathTrace.bounces");
    expectError(replaced(kLitPreset, "\"blades\": 6", "\"blades\": 2"), "camera.blades");
    expectError(replaced(kLitPreset, "\"size\": 0.5", "\"size\": 0.5, \"sizes\": 1"), "lights[0].sizes");
}

TEST(EnvironmentMap, MissingOrNonExrMapIsAClearError) {
    const ColorPipeline colors = ColorPipeline::fromFile(shippedOcioConfigPath());
    EnvironmentSettings settings;
    settings.map = "missing.exr";
    try {
        loadEnvironmentMap("/nonexistent/missing.exr", settings, colors, "scene_linear", "p.json");
        ADD_FAILURE() << "no error";
    } catch (const PresetError& e) {
        EXPECT_EQ(e.field(), "environment.map");
        EXPECT_NE(e.reason().find("does not exist"), std::string::npos);
    }
    const auto fake = std::filesystem::temp_directory_path() / "fraktal_not_an_exr.exr";
    std::ofstream(fake) << "not an image";
    EXPECT_THROW(loadEnvironmentMap(fake, settings, colors, "scene_linear", "p.json"), PresetError);
    std::filesystem::remove(fake);
    settings.colorSpace = "no such space";
    EXPECT_THROW(
        loadEnvironmentMap(test::sourceDir() / "presets/env/sky.exr", settings, colors, "scene_linear", "p.json"),
        PresetError);
}

TEST(EnvironmentMap, ImportanceSamplingIsNormalisedAndFindsTheSun) {
    const ColorPipeline colors = ColorPipeline::fromFile(shippedOcioConfigPath());
    EnvironmentSettings settings;
    settings.map = "env/sky.exr";
    const EnvironmentMap map =
        loadEnvironmentMap(test::sourceDir() / "presets/env/sky.exr", settings, colors, "scene_linear", "p.json");
    ASSERT_EQ(map.width, 256);
    // E[L / pdf] over the sampled directions is the integral of L over the sphere; compare with
    // a uniform-in-solid-angle estimate of the same integral (a Fibonacci sphere).
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    double importance = 0.0, reciprocal = 0.0;
    int nearSun = 0;
    const int n = 20000;
    vec3 brightest(0.0);
    double best = 0.0;
    for (int y = 0; y < map.height; ++y)
        for (int x = 0; x < map.width; ++x)
            if (double l = map.rgb[(size_t(y) * map.width + x) * 3]; l > best) {
                best = l;
                brightest = map.uvToDirection((x + 0.5) / map.width, (y + 0.5) / map.height);
            }
    for (int i = 0; i < n; ++i) {
        double pdf;
        const vec2 uv = randomVec2(u, rng);
        const vec3 d = map.sample(uv.x, uv.y, pdf);
        ASSERT_GT(pdf, 0.0);
        EXPECT_NEAR(pdf, map.pdf(d), 1e-9 * pdf);
        importance += map.radiance(d).g / pdf;
        reciprocal += 1.0 / pdf;
        if (dot(d, brightest) > std::cos(4.0 * M_PI / 180.0)) ++nearSun;
    }
    double uniform = 0.0;
    const int m = 400000;
    for (int i = 0; i < m; ++i) {
        const double z = 1.0 - 2.0 * (i + 0.5) / m, r = std::sqrt(1.0 - z * z), phi = i * 2.399963229728653;
        uniform += map.radiance(vec3(r * std::cos(phi), z, r * std::sin(phi))).g * 4.0 * M_PI / m;
    }
    EXPECT_NEAR(importance / n, uniform, 0.02 * uniform);
    EXPECT_GT(nearSun, n / 3) << "the sun brings most of the light and should get most samples";
    (void)reciprocal;
}

TEST(PathTracer, ApertureSamplesLieOnTheLens) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int blades : {0, 3, 6}) {
        vec2 mean(0.0);
        for (int i = 0; i < 4000; ++i) {
            const vec2 lens = randomVec2(u, rng);
            const vec2 p = sampleAperture(lens.x, lens.y, blades);
            EXPECT_LE(length(p), 1.0 + 1e-12);
            if (blades >= 3) {  // inside the polygon: within the apothem along every edge normal
                for (int k = 0; k < blades; ++k) {
                    const double a = M_PI / 2.0 + 2.0 * M_PI * (k + 0.5) / blades;
                    EXPECT_LE(p.x * std::cos(a) + p.y * std::sin(a), std::cos(M_PI / blades) + 1e-12);
                }
            }
            mean += p / 4000.0;
        }
        EXPECT_LT(length(mean), 0.05) << blades;
    }
}

struct TracedScene {
    Preset preset;
    ShadingParams shading;
    Lighting lighting;
    EnvironmentMap environment;
    PathScene scene() const {
        return PathScene{preset.formula, preset.camera, preset.render, shading, lighting, environment};
    }
};

TracedScene litScene(const std::string& text, int width, int height) {
    TracedScene s;
    s.preset = parsePreset(text, presetPath());
    s.preset.render.width = width;
    s.preset.render.height = height;
    s.preset.render.maxSteps = 96;
    s.shading = resolveShading(s.preset.shading, s.preset.render, s.preset.formula);
    s.lighting = s.preset.lighting;
    s.lighting.lights = resolveLights(s.lighting.lights);
    if (s.lighting.environment.active()) {
        const ColorPipeline colors = ColorPipeline::fromFile(shippedOcioConfigPath());
        s.environment = loadEnvironmentMap(resolveEnvironmentPath(s.lighting.environment.map, presetPath()),
                                           s.lighting.environment, colors, "scene_linear", presetPath());
    }
    return s;
}

// A Menger sponge (a fractal with crevices for the bounces) lit by the area light and the
// environment map (the sun in it casts the hard shadows), with depth of field.
const char* kMengerLit = R"({
  "format": "fraktal-preset", "version": 2,
  "formula": {"iterations": 3, "bailout": 1000, "boundRadius": 2.0, "nodes": [
    {"block": "abs_fold"}, {"block": "menger_fold"},
    {"block": "scale", "params": {"scale": 3.0, "center": [1, 1, 1]}}, {"block": "box", "params": {"size": [1, 1, 1]}}]},
  "camera": {"position": [2.2, 1.6, 2.8], "target": [0, 0, 0], "fovY": 40, "aperture": 0.03},
  "lights": [{"type": "rect", "position": [0, 2.2, 0.5], "normal": [0, -1, 0], "up": [0, 0, 1], "size": 1.2, "height": 0.8, "intensity": 3}],
  "environment": {"map": "env/sky.exr"},
  "pathTrace": {"bounces": 2}
})";

// The path tracer's draws (whole passes, and the rows the editor spreads over its frames) look up
// no uniform locations: they are found when the program is built.
TEST(PathTracer, DrawsLookUpNoUniformLocations) {
    test::glContext();
    const TracedScene s = litScene(kMengerLit, 32, 18);
    gl::PathTracer tracer(s.preset.formula, 32, 18);
    tracer.setScene(s.scene());
    const test::UniformLookups counter;
    tracer.addSamples(2, 1);
    while (!tracer.addSampleRows(6)) {
    }
    EXPECT_EQ(tracer.samplesTaken(), 3);
    EXPECT_EQ(test::UniformLookups::calls, 0);
}

TEST(PathTracer, GlConvergesToTheCpuReference) {
    test::glContext();
    const TracedScene s = litScene(kMengerLit, 64, 36);
    const int spp = 8;
    const PathImage cpu = pathTraceReference(s.scene(), 0, spp);
    gl::PathTracer tracer(s.preset.formula, 64, 36);
    tracer.setScene(s.scene());
    tracer.addSamples(spp);
    const PathImage gpu = tracer.image();
    const double psnr = meanImagePsnr(gpu, cpu);
    std::printf("GL vs CPU path tracer, 64x36 at %d spp: mean-image PSNR %.1f dB, %.0f DE evaluations per sample\n",
                spp, psnr, tracer.deEvaluationsPerSample());
    EXPECT_GE(psnr, 35.0);
    // A scene that tests something: part covered, lit directly, by bounces and by the glossy lobe.
    double coverage = 0.0, mean[kPassCount] = {};
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            coverage += cpu.at(kBeauty, x, y)[3] / (64.0 * 36.0);
            for (int pass = 0; pass < kPassCount; ++pass) mean[pass] += cpu.at(pass, x, y)[1] / (64.0 * 36.0);
        }
    std::printf("coverage %.2f, mean green: beauty %.3f, diffuse direct %.3f, indirect %.3f, specular %.3f\n", coverage,
                mean[kBeauty], mean[kDiffuseDirect], mean[kDiffuseIndirect], mean[kSpecular]);
    EXPECT_GT(coverage, 0.2);
    EXPECT_LT(coverage, 0.9);
    EXPECT_GT(mean[kDiffuseDirect], 0.01);
    EXPECT_GT(mean[kDiffuseIndirect], 0.0);
    EXPECT_GT(mean[kSpecular], 0.0);
    // The passes add up to the beauty where the surface was hit (no background there).
    for (int y = 0; y < 36; ++y)
        for (int x = 0; x < 64; ++x) {
            if (gpu.at(kBeauty, x, y)[3] < 1.0f) continue;
            for (int c = 0; c < 3; ++c) {
                const float sum = gpu.at(kDiffuseDirect, x, y)[c] + gpu.at(kDiffuseIndirect, x, y)[c] +
                                  gpu.at(kSpecular, x, y)[c] + gpu.at(kEmission, x, y)[c];
                EXPECT_NEAR(sum, gpu.at(kBeauty, x, y)[c], 1e-3f * (1.0f + sum));
            }
        }
}

// The 10 %..90 % width, in pixels, of the rising edge of `row` (coverage 0 -> 1 left to right).
double edgeWidth(const std::vector<double>& row) {
    auto crossing = [&](double level) {
        for (size_t i = 1; i < row.size(); ++i)
            if (row[i - 1] < level && row[i] >= level) return (i - 1) + (level - row[i - 1]) / (row[i] - row[i - 1]);
        return -1.0;
    };
    return crossing(0.9) - crossing(0.1);
}

// A thin slab facing the camera at depth 4 through a thin lens of radius 0.5 (fovY 10, 64x24
// pixels): its right edge (at the image centre; its left one is out of view) is a straight step in
// coverage, blurred by the lens. `edgeWidthAt(focus)` renders it focused at `focus` and returns the
// 10-90 % width in pixels of that step across the middle rows.
constexpr int kLensW = 64, kLensH = 24;
const char* const kLensBox = R"({
  "format": "fraktal-preset", "version": 2,
  "formula": {"iterations": 0, "boundRadius": 3, "nodes": [{"block": "box", "params": {"size": [1, 1, 0.02]}}]},
  "camera": {"position": [1.0, 0, 4.02], "target": [1.0, 0, 0], "fovY": 10, "aperture": 0.5, "focusDistance": FOCUS},
  "render": {"transparentBackground": true, "filterRadius": 0.5}, "pathTrace": {"bounces": 0}
})";

// The step's width from the coverage (alpha) of the rows about the centre, averaged.
template <typename AlphaAt>
double coverageEdgeWidth(AlphaAt alphaAt) {
    std::vector<double> row(kLensW, 0.0);
    for (int y = kLensH / 2 - 4; y < kLensH / 2 + 4; ++y)
        for (int x = 0; x < kLensW; ++x) row[x] += (1.0 - alphaAt(x, y)) / 8.0;
    return edgeWidth(row);
}

void expectTheCircleOfConfusion(const std::function<double(double)>& edgeWidthAt, const char* renderer) {
    // The face lies at depth z = 4. Focused there, the edge is as sharp as the pixel filter.
    const double sharp = edgeWidthAt(4.0);
    // (A one-pixel box filter's step, read between pixel centres, rises over 1.6 px.)
    EXPECT_LT(sharp, 2.0) << renderer;
    // Focused at s = 8, a point at z blurs into a disc of radius A |1 - z / s| on the plane at z;
    // a pixel there spans z * pixelAngle. A disc-blurred step rises from 10 % to 90 % over
    // 2 x0 R, with x0 solving (x sqrt(1 - x^2) + asin x) / pi = 0.4.
    const double pixelAngle = 2.0 * std::tan(5.0 * M_PI / 180.0) / kLensH;
    const double radius = 0.5 * std::abs(1.0 - 4.0 / 8.0) / (4.0 * pixelAngle);
    double x0 = 0.5;
    for (int i = 0; i < 60; ++i) {
        const double f = (x0 * std::sqrt(1.0 - x0 * x0) + std::asin(x0)) / M_PI - 0.4;
        x0 -= f / (2.0 * std::sqrt(1.0 - x0 * x0) / M_PI);
    }
    const double expected = 2.0 * x0 * radius;
    const double blurred = edgeWidthAt(8.0);
    std::printf("%s: edge width %.2f px in focus, %.2f px out of focus (thin lens: %.2f px)\n", renderer, sharp,
                blurred, expected);
    EXPECT_NEAR(blurred, expected, 0.1 * expected) << renderer;
}

TEST(PathTracer, DepthOfFieldBlursByTheCircleOfConfusion) {
    test::glContext();
    expectTheCircleOfConfusion(
        [](double focus) {
            TracedScene s = litScene(replaced(kLensBox, "FOCUS", std::to_string(focus)), kLensW, kLensH);
            gl::PathTracer tracer(s.preset.formula, kLensW, kLensH);
            tracer.setScene(s.scene());
            tracer.addSamples(256, 64);
            const PathImage image = tracer.image();
            return coverageEdgeWidth([&](int x, int y) { return image.at(kBeauty, x, y)[3]; });
        },
        "path tracer");
}

// The fast still renderer's samples average over the same lens (shaders/lens.glsl).
TEST(StillRenderer, DepthOfFieldBlursByTheCircleOfConfusion) {
    test::glContext();
    expectTheCircleOfConfusion(
        [](double focus) {
            const Preset preset = parsePreset(replaced(kLensBox, "FOCUS", std::to_string(focus)), "lens.json");
            RenderSettings r = preset.render;
            r.width = kLensW;
            r.height = kLensH;
            r.spp = 256;
            gl::StillRenderer renderer(preset.formula, 64);
            renderer.setScene(preset.formula, preset.camera, r, resolveShading(preset.shading, r, preset.formula), 0.0,
                              preset.lighting.lens);
            ImageStrip image;
            image.resize(r.width, 0, r.height);
            for (const TileRect& tile : tilesOf({0, 0, r.width, r.height}, 64)) renderer.renderTile(tile, image);
            return coverageEdgeWidth(
                [&](int x, int y) { return double(image.rgba[4 * (size_t(y) * size_t(r.width) + size_t(x)) + 3]); });
        },
        "fast still renderer");
}

// The viewport at rest: its anti-aliasing samples after the first leave their own points of the
// same lens. The slab is flat-lit on a black sky (one palette colour, no AO, shadows or specular),
// so the step in brightness is the step in coverage.
TEST(ViewportGL, DepthOfFieldAtRestBlursByTheCircleOfConfusion) {
    test::glContext();
    expectTheCircleOfConfusion(
        [](double focus) {
            std::string text = replaced(kLensBox, "FOCUS", std::to_string(focus));
            text = replaced(text, R"("pathTrace")",
                            R"("shading": {"backgroundTop": [0, 0, 0], "backgroundBottom": [0, 0, 0], "aoSteps": 0,
                              "shadowSteps": 0, "specular": 0, "paletteB": [0, 0, 0]}, "pathTrace")");
            const Preset preset = parsePreset(text, "lens.json");
            viewport::ViewportOptions options;
            options.maxSamples = 256;
            viewport::Viewport v(options);
            const viewport::Converged c =
                viewport::renderUntilSettled(v, preset.formula, preset.camera, preset.render, preset.shading, kLensW,
                                             kLensH, 4000, preset.lighting.lens);
            EXPECT_TRUE(c.settled);
            // Brightness from the sky (0) to the face (the mean of the image's brightest column).
            auto brightness = [&](int x, int y) {
                const float* p = &c.image[4 * (size_t(y) * kLensW + size_t(x))];
                return double(p[0] + p[1] + p[2]);
            };
            const double face = brightness(2, kLensH / 2);
            EXPECT_GT(face, 0.05);
            return coverageEdgeWidth([&](int x, int y) { return brightness(x, y) / face; });
        },
        "viewport at rest");
}

TEST(PathTracer, CommandLineWritesTheCompositingPasses) {
    const auto dir = std::filesystem::temp_directory_path() / "fraktal_path_cli";
    std::filesystem::create_directories(dir);
    std::ofstream(dir / "lit.json") << replaced(kLitPreset, "env/sky.exr",
                                                (test::sourceDir() / "presets/env/sky.exr").string());
    const auto exr = dir / "lit.exr";
    const test::CliRun run =
        test::runCli("render " + (dir / "lit.json").string() + " -o " + exr.string() + " --png " +
                     (dir / "lit.png").string() + " --mode path --spp 2 --size 32x18 --denoise -q");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    Imf::InputFile in(exr.c_str());
    for (const char* name : {"R", "G", "B", "A", "Z", "diffuse_direct.R", "diffuse_indirect.G", "specular.B",
                             "emission.R", "albedo.G", "N.x", "N.z"})
        EXPECT_NE(in.header().channels().findChannel(name), nullptr) << name;
    EXPECT_TRUE(std::filesystem::exists(dir / "lit.png"));
    // A missing environment map: the file, the field and the reason; no output written.
    std::ofstream(dir / "missing.json") << replaced(kLitPreset, "env/sky.exr", "no/such/sky.exr");
    const test::CliRun bad = test::runCli("render " + (dir / "missing.json").string() + " -o " +
                                          (dir / "m.exr").string() + " --mode path -q");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("environment.map"), std::string::npos) << bad.output;
    EXPECT_NE(bad.output.find("does not exist"), std::string::npos) << bad.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.exr"));
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace fraktal
