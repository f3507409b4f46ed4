// DE-Raytracer's look through `fraktal import` (core/import/frag_shading): every preset of every
// frag under tests/data/frag and tests/data/frag_import carries the lights, AO, shadows, fog,
// background and orbit-trap weights it sets into the fraktal preset, and they survive
// the preset's JSON; and each mapping's arithmetic on values worked out by hand. Also the import's
// slider ranges as FragM's editor holds them (a vec3 slider whose minimum equals its maximum is a
// direction, not a point).
#include "core/import/frag_shading.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/import/frag_import.hpp"
#include "core/scene/scene_import.hpp"
#include "test_support.hpp"

using namespace fraktal;

// Named apart from the other tests' helpers: the tests build as unity files.
namespace frag_shading_test {

std::filesystem::path importData(const std::string& name) {
    return test::sourceDir() / "tests/data/frag_import" / name;
}

ImportedScene importPreset(const std::filesystem::path& path, const std::string& preset = "") {
    return importSceneFile(path, {.lenient = true, .measure = false, .fragPreset = preset});
}

// sRGB's decoding curve, written out for the tests.
double srgbDecode(double v) { return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4); }
// FragM's display pass (BufferShader.frag) for the curves the tests' presets use: Exposure, then
// ToneMapping 1 (linear) or 4 (Reinhard, the default), then 1 / Gamma; and the linear value
// fraktal's sRGB display shows alike.
struct Display {
    double exposure = 1.0, gamma = 2.0;
    int tone = 4;
    double operator()(double v) const {
        const double c = std::max(v, 0.0) * exposure;
        return srgbDecode(std::pow(tone == 1 ? c : c / (1 + c), 1 / gamma));
    }
    vec3 operator()(const vec3& v) const { return {(*this)(v.x), (*this)(v.y), (*this)(v.z)}; }
};
// The scale of both lights: a white surface's mean brightness over the normals facing the eye
// (half of each light) shows as FragM shows it.
double lightScale(const Display& d, const vec3& key, const vec3& fill) {
    const double lit = (key.x + key.y + key.z + fill.x + fill.y + fill.z) / 6;
    return d(lit) / lit;
}

void expectNear(const vec3& got, const vec3& want, double tolerance, const std::string& what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], tolerance) << what << " [" << k << "]";
}

// The slider ranges of DE-Raytracer.frag's settings the tests read (FragM clamps a preset's value
// to them); a colour's components are clamped to [0, 1], its intensity to the range.
const std::map<std::string, std::pair<double, double>> kRanges = {{"Specular", {0, 1}},
                                                                  {"SpecularExp", {0, 100}},
                                                                  {"SpecularMax", {0, 100}},
                                                                  {"SpotLight", {0, 1}},
                                                                  {"SpotLightDir", {-1, 1}},
                                                                  {"CamLight", {0, 2}},
                                                                  {"CamLightMin", {0, 1}},
                                                                  {"AO", {0, 1}},
                                                                  {"DetailAO", {-7, 0}},
                                                                  {"Fog", {0, 2}},
                                                                  {"HardShadow", {0, 1}},
                                                                  {"ShadowSoft", {0, 20}},
                                                                  {"OrbitStrength", {0, 1}},
                                                                  {"X", {-1, 1}},
                                                                  {"Y", {-1, 1}},
                                                                  {"Z", {-1, 1}},
                                                                  {"R", {-1, 1}},
                                                                  {"Exposure", {0, 3}},
                                                                  {"Gamma", {0, 5}},
                                                                  {"BaseColor", {0, 1}},
                                                                  {"BackgroundColor", {0, 1}}};

// A preset's line for `key`, clamped as FragM clamps it; empty when the preset has none.
std::vector<double> line(const frag::FragPreset& preset, const std::string& key) {
    const frag::PresetValue* v = preset.find(key);
    if (!v) return {};
    std::vector<double> n = v->numbers;
    const auto [lo, hi] = kRanges.at(key);
    for (size_t k = 0; k < n.size(); ++k)
        n[k] = n.size() == 4 && k < 3 ? std::clamp(n[k], 0.0, 1.0) : std::clamp(n[k], lo, hi);
    if (key == "BaseColor" || key == "BackgroundColor")
        for (double& c : n) c = std::clamp(c, 0.0, 1.0);
    return n;
}

vec3 rgbOf(const std::vector<double>& v) { return vec3(v[0], v[1], v[2]); }

// The frags of the tests' folders that a preset can come from (not the include-only ones).
std::vector<std::filesystem::path> testFrags() {
    std::vector<std::filesystem::path> frags;
    for (const char* folder : {"tests/data/frag", "tests/data/frag_import"})
        for (const auto& e : std::filesystem::recursive_directory_iterator(test::sourceDir() / folder))
            if (e.path().extension() == ".frag" && e.path().parent_path().filename() != "include")
                frags.push_back(e.path());
    std::sort(frags.begin(), frags.end());
    return frags;
}

}  // namespace frag_shading_test

using namespace frag_shading_test;

TEST(FragShading, EveryTestFragsPresetCarriesItsShadingSettings) {
    std::map<std::string, int> checked;  // how many presets set each mapped setting
    int presets = 0;
    for (const std::filesystem::path& path : testFrags()) {
        const frag::FragFile file = frag::loadFragFile(path, frag::importParseOptions({}));
        if (file.doNotRun || !frag::drawnByDERaytracer(file)) continue;
        for (const frag::FragPreset& preset : file.presets) {
            if (preset.keyFrame()) continue;
            ImportedScene scene;
            try {
                scene = importPreset(path, preset.name);
            } catch (const PresetError&) {
                continue;  // a frag the import refuses (tests/data/frag_import/refuse_*.frag)
            }
            ++presets;
            const std::string where = path.filename().string() + " #preset " + preset.name;
            const Preset& p = scene.preset;
            const ShadingSettings& s = p.shading;
            const double bound = p.formula.boundRadius;
            Display display;
            if (preset.find("Gamma")) display.gamma = std::max(line(preset, "Gamma")[0], 0.1);
            if (preset.find("Exposure")) display.exposure = line(preset, "Exposure")[0];
            if (const frag::PresetValue* t = preset.find("ToneMapping")) display.tone = int(t->numbers.at(0));
            if (display.tone != 1 && display.tone != 4) continue;  // the curves Display draws
            auto has = [&](std::initializer_list<const char*> keys) {
                for (const char* k : keys)
                    if (!preset.find(k)) return false;
                for (const char* k : keys) ++checked[k];
                return true;
            };
            if (has({"SpotLightDir"})) {
                const std::vector<double> d = line(preset, "SpotLightDir");
                const double a = M_PI * d[0], b = M_PI / 2 * d[1];
                const vec3 want(std::sin(a) * std::cos(b), std::sin(b) * std::sin(a), std::cos(a));
                expectNear(s.lightDirection, normalize(want), 1e-9, where + " lightDirection");
            }
            if (has({"SpotLight", "CamLight", "CamLightMin"})) {
                const std::vector<double> l = line(preset, "SpotLight"), c = line(preset, "CamLight");
                const double m = line(preset, "CamLightMin")[0];
                const vec3 key = rgbOf(l) * l[3], fill = rgbOf(c) * (c[3] * (1 + m * m));
                const double scale = lightScale(display, key, fill);
                expectNear(s.lightColor, key * scale, 1e-9, where + " lightColor");
                expectNear(s.fillColor, fill * scale, 1e-9, where + " fillColor");
            }
            if (has({"BackgroundColor"})) {
                const std::vector<double> c = line(preset, "BackgroundColor");
                const vec3 want = display(rgbOf(c));
                expectNear(s.backgroundTop, want, 1e-9, where + " backgroundTop");
                expectNear(s.backgroundBottom, want, 1e-9, where + " backgroundBottom");
            }
            if (has({"AO"})) {
                const double w = line(preset, "AO")[3];
                EXPECT_NEAR(s.aoStrength, w, 1e-12) << where;
                EXPECT_EQ(s.aoSteps, w > 0 ? 5 : 0) << where;
                if (w > 0 && preset.find("DetailAO") && line(preset, "DetailAO")[0] < 0) {
                    EXPECT_NEAR(s.aoDistance * bound, 25 * std::pow(10.0, line(preset, "DetailAO")[0]), 1e-9) << where;
                }
            }
            if (has({"HardShadow"})) {
                // Whole from 0.5, none below: the nearer of fraktal's two.
                EXPECT_EQ(s.shadowSteps > 0, line(preset, "HardShadow")[0] >= 0.5) << where;
            }
            if (has({"ShadowSoft"})) {
                EXPECT_NEAR(s.shadowSoftness, 30 * line(preset, "ShadowSoft")[0], 1e-9) << where;
            }
            if (has({"Fog"})) {
                const double fog = line(preset, "Fog")[0];
                // Half hidden at the same distance: exp(-Fog^4 t^2) = 1 / 2 = exp(-density t).
                if (fog > 0) {
                    const double half = std::sqrt(std::log(2.0)) / (fog * fog);
                    EXPECT_NEAR(std::exp(-s.fogDensity / bound * half), 0.5, 1e-9) << where;
                } else {
                    EXPECT_EQ(s.fogDensity, 0.0) << where;
                }
            }
            if (has({"X", "Y", "Z", "R"})) {
                for (int i = 0; i < 4; ++i)
                    EXPECT_NEAR(s.trapWeights[i], line(preset, std::string(1, "XYZR"[i]))[3], 1e-12) << where;
            }
            if (has({"OrbitStrength", "BaseColor"}) && !file.provides.count("providesColor")) {
                // The colour at trap index 0: (1 - OrbitStrength) BaseColor where the palette ramps
                // (CycleColors off), BaseColor alone where OrbitStrength is 0.
                const double strength = line(preset, "OrbitStrength")[0];
                const vec3 base = rgbOf(line(preset, "BaseColor"));
                const frag::PresetValue* cycle = preset.find("CycleColors");
                if (!(cycle && cycle->boolean.value_or(false))) {
                    const vec3 at0 = s.paletteA + s.paletteB * glm::cos(2 * M_PI * s.paletteD);
                    expectNear(at0, (1 - strength) * base, 1e-9, where + " palette at index 0");
                }
            }
            // FragM's Exposure is in the display pass the colours went through: fraktal's stays 0.
            EXPECT_EQ(p.render.exposure, 0.0) << where;
            // The preset written holds the mapped values as they are.
            const Preset back = parsePreset(serializePreset(p), where);
            EXPECT_EQ(back.shading, s) << where;
            EXPECT_EQ(back.render.exposure, p.render.exposure) << where;
        }
    }
    EXPECT_GE(presets, 10);
    // Each mapping was met by at least two presets (the folders' frags are written to set them).
    for (const char* key : {"SpotLightDir", "SpotLight", "CamLight", "BackgroundColor", "AO", "HardShadow",
                            "ShadowSoft", "Fog", "X", "OrbitStrength", "CamLightMin"})
        EXPECT_GE(checked[key], 2) << key;
}

TEST(FragShading, SpotLightDirIsSphericalHalfTurns) {
    expectNear(frag::spotLightDirection(0.0, 0.0), vec3(0, 0, 1), 1e-12, "(0, 0)");
    expectNear(frag::spotLightDirection(0.5, 0.0), vec3(1, 0, 0), 1e-12, "(0.5, 0): a quarter turn from z to x");
    expectNear(frag::spotLightDirection(0.5, 1.0), vec3(0, 1, 0), 1e-12, "(0.5, 1): up to y");
    expectNear(frag::spotLightDirection(-0.5, 0.0), vec3(-1, 0, 0), 1e-12, "(-0.5, 0)");
    expectNear(frag::spotLightDirection(1.0, 0.3), vec3(0, 0, -1), 1e-12, "(1, y): behind, whatever y");
    // (0.25, 0.5): both angles 45 degrees.
    expectNear(frag::spotLightDirection(0.25, 0.5), vec3(0.5, 0.5, std::sqrt(0.5)), 1e-12, "(0.25, 0.5)");
    // DE-Raytracer's default (0.1, 0.1): mostly toward +z, a little toward x and y.
    const vec3 d = frag::spotLightDirection(0.1, 0.1);
    EXPECT_NEAR(length(d), 1.0, 1e-12);
    EXPECT_NEAR(d.z, std::cos(0.1 * M_PI), 1e-12);
}

TEST(FragShading, FragMsDisplayPassShowsAlikeInFraktal) {
    // Linear at Gamma 2: 0.25 is shown as 0.5, which sRGB decodes to 0.2140.
    EXPECT_NEAR((frag::FragMDisplay{1.0, 1, 2.0}).linear(vec3(0.25)).x, 0.21404114, 1e-7);
    // Gamma 2.2: 0.5 is shown as 0.7297, decoded to 0.4910 (near 0.5: the curves nearly agree).
    EXPECT_NEAR((frag::FragMDisplay{1.0, 1, 2.2}).linear(vec3(0.5)).y, 0.4910, 1e-3);
    // Exposure 2 doubles before the curve.
    EXPECT_NEAR((frag::FragMDisplay{2.0, 1, 2.0}).shown(0.125), 0.5, 1e-12);
    // Reinhard (FragM's default curve): 1 becomes 1 / 2, shown at Gamma 2 as 0.7071.
    EXPECT_NEAR((frag::FragMDisplay{1.0, 4, 2.0}).shown(1.0), std::sqrt(0.5), 1e-12);
    // Exponential: 1 - e^-1 = 0.6321 at Gamma 1.
    EXPECT_NEAR((frag::FragMDisplay{1.0, 2, 1.0}).shown(1.0), 1 - std::exp(-1.0), 1e-12);
    // Filmic: about 0.5 shown at 0.18 (its own gamma raised back, at Gamma 2.2).
    EXPECT_NEAR((frag::FragMDisplay{1.0, 3, 2.2}).shown(0.18), 0.5, 0.03);
    // A curve FragM has beyond 4 (Syntopia's, Lottes', ...) is drawn as Reinhard's.
    EXPECT_EQ((frag::FragMDisplay{1.0, 7, 2.0}).shown(3.0), (frag::FragMDisplay{1.0, 4, 2.0}).shown(3.0));
    // Black stays, a negative value is black; above 1 a linear curve shows white and beyond.
    expectNear((frag::FragMDisplay{1.0, 1, 1.7}).linear(vec3(1.0, 0.0, -0.3)), vec3(1, 0, 0), 1e-12, "white, black");
}

TEST(FragShading, EachSettingMapsByItsOwnArithmetic) {
    const ImportedScene scene = importPreset(importData("shading.frag"));
    const ShadingSettings& s = scene.preset.shading;
    const double bound = scene.preset.formula.boundRadius;
    // Gamma 2.2, Exposure 1.4, ToneMapping 1 (linear).
    auto shown = [](double v) { return srgbDecode(std::pow(1.4 * v, 1 / 2.2)); };
    // SpotLight 1,0.9,0.8 at 0.6 toward SpotLightDir 0.35,-0.4; CamLight 0.9,0.95,1 at 0.8 with
    // CamLightMin 0.3 (a mean of 0.5 + 0.3^2 / 2 over the 0.5 of fraktal's fill). Both scaled so
    // that a white surface's mean, half their sum (4.1052 / 6 in the mean channel), shows as FragM
    // shows it.
    const double scale = shown(4.1052 / 6) / (4.1052 / 6);
    expectNear(s.lightColor, vec3(0.6, 0.54, 0.48) * scale, 1e-12, "lightColor");
    expectNear(s.fillColor, vec3(0.9, 0.95, 1) * (0.8 * 1.09) * scale, 1e-12, "fillColor");
    const double a = 0.35 * M_PI, b = -0.2 * M_PI;
    expectNear(s.lightDirection, vec3(std::sin(a) * std::cos(b), std::sin(b) * std::sin(a), std::cos(a)), 1e-12,
               "lightDirection");
    // The highlight's peak: min(SpecularMax 8, (20 + 2) / 8 x 20 x 0.5 = 27.5) = 8 of the light's
    // colour, as the display shows it, over the key light's mean.
    EXPECT_NEAR(s.specular, shown(8.0) / (0.54 * scale), 1e-12);
    EXPECT_EQ(s.shininess, 20.0);
    // Shadows on (HardShadow 1), ShadowSoft 4: penumbra 30 x 4.
    EXPECT_GT(s.shadowSteps, 0);
    EXPECT_EQ(s.shadowSoftness, 120.0);
    // AO 0.6 reaching 25 x 10^-1.5 = 0.7906 from the surface.
    EXPECT_EQ(s.aoStrength, 0.6);
    EXPECT_EQ(s.aoSteps, 5);
    EXPECT_NEAR(s.aoDistance * bound, 0.790569, 1e-6);
    // Fog 0.4 hides half at sqrt(ln 2) / 0.16 = 5.2035 in FragM: fraktal's density is ln 2 / 5.2035,
    // 0.13321 per unit, toward the background.
    EXPECT_NEAR(s.fogDensity / bound, 0.133209, 1e-6);
    expectNear(s.fogColor, s.backgroundTop, 0.0, "fog toward the background");
    expectNear(s.backgroundTop, vec3(shown(0.2), shown(0.3), shown(0.5)), 1e-12, "background");
    // Orbit-trap weights: the intensities of X, Y, Z (negative), R.
    EXPECT_EQ(s.trapWeights, glm::dvec4(0.7, 0.4, -0.5, 0.12));
    // The palette: (1 - 0.6) BaseColor at index 0, rising along the weights' mean colour.
    auto palette = [&](double x) {
        return s.paletteA + s.paletteB * glm::cos(2 * M_PI * (s.paletteC * x + s.paletteD));
    };
    expectNear(palette(0.0), 0.4 * vec3(0.9, 0.8, 0.7), 1e-12, "palette at 0");
    const vec3 mean =
        (0.7 * vec3(0.5, 0.6, 0.6) + 0.4 * vec3(1, 0.6, 0) + 0.5 * vec3(0.8, 0.78, 1) + 0.12 * vec3(0.4, 0.7, 1)) /
        1.72;
    const vec3 rise = palette(0.05) - palette(0.0);
    expectNear(rise / length(rise), mean / length(mean), 1e-6, "the palette rises along the mean colour");
    // Exposure is in the colours: fraktal's own stays.
    EXPECT_EQ(scene.preset.render.exposure, 0.0);
    // What fraktal draws otherwise is named, and a strict import takes the frag: shading is cosmetic.
    auto named = [&](const std::string& what) {
        return std::any_of(scene.approximated.begin(), scene.approximated.end(),
                           [&](const std::string& a) { return a.starts_with(what + ":"); });
    };
    EXPECT_TRUE(named("Glow"));
    EXPECT_TRUE(named("Fog"));
    EXPECT_TRUE(named("CamLight"));
    EXPECT_FALSE(named("ToneMapping"));  // ToneMapping 1: linear, as fraktal's display
    EXPECT_FALSE(named("GradientBackground"));
    EXPECT_NO_THROW(importSceneFile(importData("shading.frag"), {.measure = false}));
}

TEST(FragShading, CyclingFlatAndClampedPresets) {
    // CycleColors: a cosine palette over the index at Cycles / 2 pi turns per unit, phased by the
    // weights' mean colour (X at 1 and Z at 0.5 here, as phases in radians).
    const ImportedScene cycling = importPreset(importData("shading.frag"), "Cycling");
    const ShadingSettings& c = cycling.preset.shading;
    expectNear(c.paletteC, vec3(3.5 / (2 * M_PI)), 1e-12, "cycles");
    expectNear(c.paletteD, (vec3(0.1, 0.5, 0.9) * 1.0 + vec3(0.8, 0.78, 1) * 0.5) / 1.5 / (2 * M_PI), 1e-12, "phase");
    // DetailAO 0 (AO by step count) and a coloured AO are named; HardShadow 0.3 is drawn without
    // shadows (fraktal's are whole or none, and none is nearer).
    EXPECT_EQ(c.shadowSteps, 0);
    for (const char* what : {"DetailAO:", "AO:", "HardShadow:", "CycleColors:", "ToneMapping:"})
        EXPECT_TRUE(std::any_of(cycling.approximated.begin(), cycling.approximated.end(), [&](const std::string& a) {
            return a.starts_with(what);
        })) << what;

    // OrbitStrength 0: BaseColor alone; AO 0 and HardShadow 0 turn them off; FragM's clamps apply
    // (Specular 1.6 to 1, BackgroundColor to [0, 1]); SpotLightDir 1 points along -z.
    const ImportedScene flat = importPreset(importData("shading.frag"), "Flat");
    const ShadingSettings& f = flat.preset.shading;
    expectNear(f.paletteA, vec3(0.25, 0.5, 0.75), 1e-12, "flat colour");
    expectNear(f.paletteB, vec3(0.0), 0.0, "no variation");
    EXPECT_EQ(f.aoSteps, 0);
    EXPECT_EQ(f.shadowSteps, 0);
    EXPECT_EQ(f.fogDensity, 0.0);
    expectNear(f.lightDirection, vec3(0, 0, -1), 1e-12, "SpotLightDir 1, 0.7");
    // Specular clamped to 1: min(10, (16 + 2) / 8 x 16 x 1 = 36) = 10 over the default 0.4 (Gamma 2).
    // The raytracer's defaults where the preset is silent: SpotLight 1 at 0.4, CamLight 1 at 1,
    // Reinhard's curve at Gamma 2 (named).
    const Display reinhard;
    const double scale = reinhard(0.7) / 0.7;
    expectNear(f.lightColor, vec3(0.4 * scale), 1e-12, "default SpotLight");
    expectNear(f.fillColor, vec3(scale), 1e-12, "default CamLight");
    EXPECT_NEAR(f.specular, reinhard(10.0) / (0.4 * scale), 1e-12);
    expectNear(f.backgroundTop, reinhard(vec3(1.0, 0.0, 0.5)), 1e-12, "background clamped");
    EXPECT_EQ(flat.preset.render.exposure, 0.0);
}

TEST(FragShading, AoAndFogKeepTheirWorldLengthsWhenTheBoundIsFitted) {
    // `fraktal import` measures the step on the GPU and fits the bound to the object; FragM's
    // lengths stay.
    const test::Sandbox box("fraktal_frag_shading_");
    const std::string out = box.path("shading.json");
    const auto imported = test::runCli("import '" + importData("shading.frag").string() + "' -o '" + out + "'");
    ASSERT_EQ(imported.exitCode, 0) << imported.output;
    const Preset p = loadPreset(out);
    EXPECT_LT(p.formula.boundRadius, importPreset(importData("shading.frag")).preset.formula.boundRadius);
    EXPECT_NEAR(p.shading.aoDistance * p.formula.boundRadius, 25 * std::pow(10.0, -1.5), 1e-9);
    EXPECT_NEAR(p.shading.fogDensity / p.formula.boundRadius, std::sqrt(std::log(2.0)) * 0.16, 1e-9);
}

TEST(FragShading, ARaytracerOtherThanDERaytracerKeepsFraktalsShading) {
    const std::string frag = R"(#include "Soft-Raytracer.frag"
float DE(vec3 p) { return length(p) - 1.0; }
#preset Default
Eye = 0,0,4
SpotLight = 1,0,0,1
BackgroundColor = 1,0,0
#endpreset
)";
    const frag::FragFile file = frag::parseFragFile(frag, "soft.frag", frag::importParseOptions({}));
    EXPECT_FALSE(frag::drawnByDERaytracer(file));
    const frag::FragImport result = frag::importFrag(file);
    EXPECT_EQ(result.preset.shading, ShadingSettings{});
    ASSERT_FALSE(result.approximated.empty());
    EXPECT_NE(result.approximated.back().text().find("not DE-Raytracer"), std::string::npos);
}

TEST(FragImport, DirectionSliderKeepsItsValueAsFragMDoes) {
    // slider[(0,0,0),(0,1,0),(0,0,0)]: FragM's editor spans each component over [-1, 1] (3D.frag's
    // Up is such a slider); the preset's 0.6,-0.8,0 stays, where a range of one point held it at 0.
    const ImportedScene scene = importPreset(importData("direction_slider.frag"));
    const Formula& f = scene.preset.formula;
    const auto& params = f.customBlocks.at(0)->definition().params;
    const auto axis = std::find_if(params.begin(), params.end(), [](const auto& p) { return p.name == "Axis"; });
    ASSERT_NE(axis, params.end());
    EXPECT_EQ(axis->min, -1.0);
    EXPECT_EQ(axis->max, 1.0);
    EXPECT_EQ(axis->defaultValue, vec3(0, 1, 0));
    const size_t i = size_t(axis - params.begin());
    EXPECT_EQ(f.estimator.values.at(i), vec3(0.6, -0.8, 0.0));
    // slider[1.5,0.5,1], its range written backwards: FragM's spin box holds its minimum, 1.5.
    const auto length = std::find_if(params.begin(), params.end(), [](const auto& p) { return p.name == "Length"; });
    ASSERT_NE(length, params.end());
    EXPECT_EQ(length->min, 1.5);
    EXPECT_EQ(length->max, 1.5);
    EXPECT_EQ(f.estimator.values.at(size_t(length - params.begin())).x, 1.5);
}
