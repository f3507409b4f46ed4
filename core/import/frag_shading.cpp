#include "core/import/frag_shading.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace fraktal::frag {

namespace {

// One of DE-Raytracer's (and 3D.frag's) settings: its default and its slider's range. Colours with
// an intensity hold (r, g, b, intensity): the colour is clamped to [0, 1], the intensity to the
// range; plain colours (r, g, b) to [0, 1].
struct Setting {
    std::string_view name;
    std::vector<double> value;
    double min, max;  // the range of the scalar, of each component, or of a colour's intensity
    enum Kind { Slider, Colour, ColourIntensity } kind = Slider;
};

// The defaults and ranges as FragM's Include/DE-Raytracer.frag and 3D.frag declare them.
const std::vector<Setting>& settings() {
    static const std::vector<Setting> table = {
        {"DetailAO", {-0.5}, -7.0, 0.0},
        {"AO", {0.0, 0.0, 0.0, 0.7}, 0.0, 1.0, Setting::ColourIntensity},
        {"Specular", {0.4}, 0.0, 1.0},
        {"SpecularExp", {16.0}, 0.0, 100.0},
        {"SpecularMax", {10.0}, 0.0, 100.0},
        {"SpotLight", {1.0, 1.0, 1.0, 0.4}, 0.0, 1.0, Setting::ColourIntensity},
        {"SpotLightDir", {0.1, 0.1}, -1.0, 1.0},
        {"CamLight", {1.0, 1.0, 1.0, 1.0}, 0.0, 2.0, Setting::ColourIntensity},
        {"CamLightMin", {0.0}, 0.0, 1.0},
        {"Glow", {1.0, 1.0, 1.0, 0.0}, 0.0, 1.0, Setting::ColourIntensity},
        {"Fog", {0.0}, 0.0, 2.0},
        {"HardShadow", {0.0}, 0.0, 1.0},
        {"ShadowSoft", {2.0}, 0.0, 20.0},
        {"Reflection", {0.0}, 0.0, 1.0},
        {"BaseColor", {1.0, 1.0, 1.0}, 0.0, 1.0, Setting::Colour},
        {"OrbitStrength", {0.0}, 0.0, 1.0},
        {"X", {0.5, 0.6, 0.6, 0.7}, -1.0, 1.0, Setting::ColourIntensity},
        {"Y", {1.0, 0.6, 0.0, 0.4}, -1.0, 1.0, Setting::ColourIntensity},
        {"Z", {0.8, 0.78, 1.0, 0.5}, -1.0, 1.0, Setting::ColourIntensity},
        {"R", {0.4, 0.7, 1.0, 0.12}, -1.0, 1.0, Setting::ColourIntensity},
        {"BackgroundColor", {0.6, 0.6, 0.45}, 0.0, 1.0, Setting::Colour},
        {"GradientBackground", {0.3}, 0.0, 5.0},
        {"Cycles", {1.1}, 0.1, 32.3},
        {"Gamma", {2.0}, 0.0, 5.0},
        {"ToneMapping", {4.0}, 1.0, 9.0},
        {"Exposure", {1.0}, 0.0, 3.0},
    };
    return table;
}

// The setting's value: the preset's line where it has one of the setting's size, else the default;
// clamped as FragM clamps a preset's value to the slider.
std::vector<double> valueOf(const FragPreset* preset, std::string_view name) {
    const auto& table = settings();
    const auto it = std::find_if(table.begin(), table.end(), [&](const Setting& s) { return s.name == name; });
    std::vector<double> v = it->value;
    if (preset)
        if (const PresetValue* line = preset->find(name); line && line->numbers.size() == v.size()) v = line->numbers;
    for (size_t k = 0; k < v.size(); ++k) {
        const bool intensity = it->kind == Setting::ColourIntensity && k == 3;
        const bool colour = it->kind == Setting::Colour || (it->kind == Setting::ColourIntensity && k < 3);
        v[k] = colour && !intensity ? std::clamp(v[k], 0.0, 1.0) : std::clamp(v[k], it->min, it->max);
    }
    return v;
}

double scalar(const FragPreset* preset, std::string_view name) { return valueOf(preset, name)[0]; }
vec3 rgb(const std::vector<double>& v) { return vec3(v[0], v[1], v[2]); }

bool checked(const FragPreset* preset, std::string_view name) {
    const PresetValue* line = preset ? preset->find(name) : nullptr;
    return line && line->boolean.value_or(false);  // CycleColors: checkbox[false]
}

std::string fmt(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v);
    return buf;
}

double srgbToLinear(double v) {
    v = std::max(v, 0.0);
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

}  // namespace

bool drawnByDERaytracer(const FragFile& file) {
    return std::any_of(file.files.begin(), file.files.end(),
                       [](const SourceFile& f) { return f.includeName.starts_with("DE-Raytracer"); });
}

vec3 spotLightDirection(double x, double y) {
    const double a = M_PI * x, b = 0.5 * M_PI * y;
    const vec3 d(std::sin(a) * std::cos(b), std::sin(b) * std::sin(a), std::cos(a));
    // SpotLightDir (0, y) and (1, y) point along z whatever y: the formula's length is 1 there too.
    return length(d) > 1e-12 ? normalize(d) : vec3(0.0, 0.0, 1.0);
}

double FragMDisplay::shown(double v) const {
    double c = std::max(v, 0.0) * exposure;
    switch (toneMapping) {
        case 1: break;
        case 2: c = 1.0 - std::exp(-c); break;
        case 3: {
            // Hejl and Burgess-Dawson's filmic curve, which holds a gamma of 2.2 of its own: FragM
            // raises it back by 2.2 before its 1 / Gamma.
            const double x = std::max(c - 0.004, 0.0);
            c = std::pow(x * (6.2 * x + 0.5) / (x * (6.2 * x + 1.7) + 0.06), 2.2);
            break;
        }
        default: c = c / (1.0 + c);
    }
    // Above 1 (the linear curve's) the screen shows white; fraktal's display clips alike.
    return std::pow(std::max(c, 0.0), 1.0 / std::max(gamma, 0.1));
}

vec3 FragMDisplay::linear(const vec3& v) const {
    return vec3(srgbToLinear(shown(v.x)), srgbToLinear(shown(v.y)), srgbToLinear(shown(v.z)));
}

RaytracerLook raytracerLook(const FragFile& file, const FragPreset* preset) {
    RaytracerLook look;
    ShadingSettings& s = look.shading;
    auto approximated = [&](const std::string& where, const std::string& what) {
        look.approximated.push_back({where, what});
    };
    FragMDisplay display;
    display.exposure = scalar(preset, "Exposure");
    display.toneMapping = int(std::lround(scalar(preset, "ToneMapping")));
    display.gamma = std::max(scalar(preset, "Gamma"), 0.1);

    // The key light: SpotLight's colour times its intensity, toward SpotLightDir. The light from the
    // eye, max(CamLightMin, cos) times CamLight, is fraktal's fill light (from the sky, 0.5 + 0.5 n.y,
    // 0.5 on average over the normals facing the eye) with the same mean: max(m, cos) averages
    // 0.5 + m^2 / 2 over those normals.
    const std::vector<double> spot = valueOf(preset, "SpotLight");
    const std::vector<double> spotDir = valueOf(preset, "SpotLightDir");
    const std::vector<double> cam = valueOf(preset, "CamLight");
    const double camMin = scalar(preset, "CamLightMin");
    const vec3 key = rgb(spot) * spot[3];
    const vec3 fill = rgb(cam) * (cam[3] * (1.0 + camMin * camMin));
    // Both scaled alike, so that a white surface shows its mean brightness over the normals facing
    // the eye, half of each light (cosines average 0.5), as FragM's display shows it.
    const double lit = (key.x + key.y + key.z + fill.x + fill.y + fill.z) / 6.0;
    const double scale = lit > 1e-9 ? display.linear(vec3(lit)).x / lit : 0.0;
    s.lightDirection = spotLightDirection(spotDir[0], spotDir[1]);
    s.lightColor = key * scale;
    s.fillColor = fill * scale;
    // DE-Raytracer's highlight peaks (where the half vector meets the normal) at
    // min(SpecularMax, (SpecularExp + 2) / 8 * SpecularExp * Specular) times the light's colour,
    // without its intensity; fraktal's at specular times lightColor: the peak shows as FragM's
    // display shows it. The same exponent keeps the highlight's width.
    const double exponent = scalar(preset, "SpecularExp");
    const double peak =
        std::min(scalar(preset, "SpecularMax"), (exponent + 2.0) / 8.0 * exponent * scalar(preset, "Specular"));
    const double keyGrey = (s.lightColor.x + s.lightColor.y + s.lightColor.z) / 3.0;
    s.specular = keyGrey > 1e-9 ? std::clamp(display.linear(vec3(peak)).x / keyGrey, 0.0, 100.0) : 0.0;
    s.shininess = std::max(exponent, 1.0);
    if (peak > 0.0 && keyGrey <= 1e-9)
        approximated("Specular", "a highlight of a spot light of intensity 0: fraktal's highlight is the key light's");
    approximated("CamLight",
                 "FragM's light from the eye is fraktal's fill light of the same mean brightness, lighting from "
                 "above");

    // Shadows: FragM dims the key light's diffuse term by HardShadow where the shadow ray is blocked
    // (none traced at 0); fraktal's shadows are whole or none, so they are drawn from HardShadow 0.5,
    // the nearer of the two (0.35 keeps 65 % of the light in the shade: none is nearer than whole;
    // the Mandelbulb example's crevices were 17 of 255 darker with them). ShadowSoft's penumbra is
    // min(30 ShadowSoft d / t) along the shadow ray, fraktal's min(shadowSoftness d / t).
    const double hardShadow = scalar(preset, "HardShadow");
    s.shadowSteps = hardShadow >= 0.5 ? s.shadowSteps : 0;
    s.shadowSoftness = std::clamp(30.0 * scalar(preset, "ShadowSoft"), 0.1, 1000.0);
    if (hardShadow > 0.0 && hardShadow < 1.0)
        approximated("HardShadow", "HardShadow " + fmt(hardShadow) +
                                       " dims the light in the shade partly; fraktal's "
                                       "shadows are whole or none, here " +
                                       (hardShadow >= 0.5 ? "whole" : "none"));

    // Ambient occlusion: AO's intensity is the strength; DetailAO < 0 samples five points along the
    // normal at i^2 10^DetailAO (i = 1..5), fraktal at even steps to aoDistance: the farthest
    // sample is kept. DetailAO >= 0 is DE-Raytracer's AO by the march's step count.
    const std::vector<double> ao = valueOf(preset, "AO");
    const double detailAO = scalar(preset, "DetailAO");
    s.aoStrength = std::clamp(ao[3], 0.0, 1.0);
    s.aoSteps = s.aoStrength > 0.0 ? 5 : 0;
    if (s.aoSteps > 0 && detailAO < 0.0) look.aoReach = 25.0 * std::pow(10.0, detailAO);
    if (s.aoSteps > 0 && detailAO >= 0.0)
        approximated("DetailAO",
                     "AO by the march's step count (DetailAO " + fmt(detailAO) + ") is fraktal's AO along the normal");
    if (s.aoSteps > 0 && rgb(ao) != vec3(0.0))
        approximated("AO", "the occlusion's colour (" + fmt(ao[0]) + ", " + fmt(ao[1]) + ", " + fmt(ao[2]) +
                               ") is black in fraktal");

    // The background: BackgroundColor, flat (fraktal's gradient with both ends alike).
    const vec3 background = display.linear(rgb(valueOf(preset, "BackgroundColor")));
    s.backgroundTop = s.backgroundBottom = background;
    if (const double vignette = scalar(preset, "GradientBackground"); vignette > 0.0)
        approximated("GradientBackground",
                     "the background's darkening toward the corners (" + fmt(vignette) + ") is not drawn");
    if (file.provides.count("providesBackground"))
        approximated("backgroundColor", "the frag's own background (providesBackground) is BackgroundColor");

    // Fog: FragM's fades to the background by 1 - exp(-Fog^4 t^2), fraktal's by 1 - exp(-density t);
    // the two hide half at the same distance, sqrt(ln 2) / Fog^2 (the camera's target is no measure
    // of where the surfaces are: a pseudo-Kleinian's eye looks far past the columns near it).
    const double fog = scalar(preset, "Fog");
    if (fog > 0.0) {
        s.fogColor = background;
        look.fogPerUnit = std::sqrt(std::log(2.0)) * fog * fog;
        approximated("Fog",
                     "FragM's fog grows with the square of the distance; fraktal's hides half at the same "
                     "distance, more nearer and less farther");
    }
    if (const std::vector<double> glow = valueOf(preset, "Glow"); glow[3] > 0.0)
        approximated("Glow", "the glow near the object (" + fmt(glow[3]) + ") is not drawn");

    // Reflection mixes in the mirrored ray's colour by that share; fraktal's is a Fresnel
    // reflectance, the share at normal incidence.
    s.reflection = scalar(preset, "Reflection");
    if (s.reflection > 0.0) approximated("Reflection", "the mirror's share rises toward grazing angles in fraktal");

    // Orbit-trap colouring: mix(BaseColor, 3 (X x + Y y + Z z + R r), OrbitStrength) with the
    // colours scaled by their intensities (weights), and (x, y, z, r) the orbit's trap (r the root of
    // FragM's w, as fraktal's whole-DE trap is). fraktal colours by one index, dot(weights, trap):
    // the weights are the intensities and the colour follows the weights' mean colour.
    const vec3 base = rgb(valueOf(preset, "BaseColor"));
    const double strength = scalar(preset, "OrbitStrength");
    const std::vector<double> trapColours[4] = {valueOf(preset, "X"), valueOf(preset, "Y"), valueOf(preset, "Z"),
                                                valueOf(preset, "R")};
    vec3 mean(0.0);
    double weightSum = 0.0;
    for (int i = 0; i < 4; ++i) {
        s.trapWeights[i] = trapColours[i][3];
        mean += rgb(trapColours[i]) * std::abs(trapColours[i][3]);
        weightSum += std::abs(trapColours[i][3]);
    }
    if (weightSum > 0.0) mean /= weightSum;
    s.trapScale = 1.0;
    s.trapOffset = 0.0;
    const bool ownColour = file.provides.count("providesColor") > 0;
    if (strength <= 0.0 || weightSum <= 0.0 || ownColour) {
        // The surface is BaseColor alone (the frag's own colour, where it has one, is named by the
        // import): a flat palette.
        s.paletteA = base * (ownColour ? 1.0 : 1.0 - strength);
        s.paletteB = s.paletteD = vec3(0.0);
        s.paletteC = vec3(1.0);
    } else if (!checked(preset, "CycleColors")) {
        // The colour rises along the mean colour from (1 - s) BaseColor at index 0; a cosine from its
        // trough to its crest follows it up to the index where FragM's colour stops at 1 (clamped).
        const vec3 slope = 3.0 * strength * mean;
        const vec3 start = (1.0 - strength) * base;
        double top = 0.0;
        for (int k = 0; k < 3; ++k)
            if (slope[k] > 1e-9) top = std::max(top, (1.0 - start[k]) / slope[k]);
        top = top > 0.0 ? std::clamp(top, 0.25, 4.0) : 1.0;
        s.paletteA = start + 0.5 * top * slope;
        s.paletteB = 0.5 * top * slope;
        s.paletteC = vec3(0.5 / top);
        s.paletteD = vec3(0.5);
        approximated("OrbitStrength", "the orbit-trap colours X, Y, Z, R are one ramp along their mean colour");
    } else {
        // CycleColors: each colour's term is (0.5 + 0.5 cos(Cycles t + colour)) weight t, the colour
        // a phase in radians; fraktal's cosine palette cycles by the index at the mean phase, with
        // the amplitude the terms have at index 0.5.
        const double cycles = scalar(preset, "Cycles");
        const double amplitude = 0.5 * 3.0 * strength * 0.5;
        s.paletteA = (1.0 - strength) * base + vec3(amplitude);
        s.paletteB = vec3(amplitude);
        s.paletteC = vec3(cycles / (2.0 * M_PI));
        s.paletteD = mean / (2.0 * M_PI);
        approximated("CycleColors",
                     "the cycling orbit-trap colours are one cosine palette over the index, at "
                     "the colours' mean phase");
    }

    if (display.toneMapping != 1)
        approximated("ToneMapping", "FragM's tone curve " + std::to_string(display.toneMapping) +
                                        (display.toneMapping > 4 ? " (drawn as Reinhard's, 4)" : "") +
                                        " holds for the background and a white surface facing the lights; "
                                        "fraktal's display is linear elsewhere");
    return look;
}

}  // namespace fraktal::frag
