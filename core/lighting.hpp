// Print-quality light for the path-traced mode: a list of lights, an HDR environment map and a
// thin-lens camera, as the preset's "lights", "environment" and camera lens fields describe them
// (presets/README.md, "Lights"). Plain data plus its JSON reading and writing; the environment
// map's pixels are loaded when a scene is built (core/image/environment.hpp), not here.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/json_reader.hpp"
#include "core/vec.hpp"

namespace fraktal {

inline constexpr int kMaxLights = 16;

enum class LightType { Directional, Sphere, Rect };

// The one table of light type names: each type's "type" in presets (and an alias the reader also
// takes), and its label in the editor, in the enum's order.
struct LightTypeNames {
    LightType type;
    const char* name;   // written to presets
    const char* alias;  // also read, or null
    const char* label;  // the editor's
};
inline constexpr LightTypeNames kLightTypeNames[] = {
    {LightType::Directional, "directional", nullptr, "Directional"},
    {LightType::Sphere, "sphere", "point", "Sphere"},
    {LightType::Rect, "rect", nullptr, "Rect"},
};
const LightTypeNames& lightTypeNames(LightType type);

// Intensities are radiometric-ish: a directional light's `intensity` is the irradiance it gives a
// surface facing it; a sphere light's is its radiant intensity (irradiance at distance 1 facing
// it, falling off as 1/d^2); a rectangle's is its radiance (emitted per unit area and solid angle).
struct Light {
    LightType type = LightType::Directional;
    bool enabled = true;
    vec3 color{1.0};
    double intensity = 1.0;
    vec3 direction{0.55, 0.75, 0.35};  // directional: toward the light (normalised on use)
    vec3 position{0.0, 3.0, 0.0};      // sphere, rect: centre
    // Directional: angular radius in degrees (the sun is 0.27); sphere: radius; rect: width.
    double size = 0.0;
    double height = 1.0;          // rect: its extent along `up`
    vec3 normal{0.0, -1.0, 0.0};  // rect: the side it emits toward
    vec3 up{0.0, 0.0, 1.0};       // rect: the direction of its `height` edge

    bool operator==(const Light&) const = default;
};

// An equirectangular, scene-linear EXR (longitude along x, +y up at the top row).
struct EnvironmentSettings {
    std::string map;                                   // path, relative to the preset file; empty: no map
    std::string colorSpace = "Linear Rec.709 (sRGB)";  // OCIO space of the map's pixels
    double intensity = 1.0;
    double rotation = 0.0;  // degrees about +y
    bool visible = true;    // seen as the background by camera rays

    bool active() const { return !map.empty(); }
    bool operator==(const EnvironmentSettings&) const = default;
};

// A thin lens (pbrt-v4 6.2.3): rays start on a disc (or polygon with `blades` sides) of radius
// apertureRadius about the camera position and pass through the point of the pinhole ray that lies
// at focusDistance along the view axis, so that plane is sharp.
struct ThinLens {
    double apertureRadius = 0.0;  // world units; 0: pinhole (no depth of field)
    double focusDistance = 0.0;   // along the view axis; 0: the distance to camera.target
    int blades = 0;               // 0: round aperture; 3..16: polygonal

    bool enabled() const { return apertureRadius > 0.0; }
    bool operator==(const ThinLens&) const = default;
};

// The distance along the view axis that the lens focuses at: its own, else the camera's target's.
double focusDistanceOf(const ThinLens& lens, const Camera& camera);

// The path tracer's own settings ("pathTrace").
struct PathTraceSettings {
    int bounces = 3;          // surface interactions after the first hit
    double roughness = 0.35;  // GGX roughness of the glossy lobe
    double specular = 0.04;   // its reflectance at normal incidence (the Fresnel F0)
    double emission = 0.0;    // the albedo glows with this radiance factor
    bool operator==(const PathTraceSettings&) const = default;
};

struct Lighting {
    std::vector<Light> lights;
    EnvironmentSettings environment;
    ThinLens lens;
    PathTraceSettings pathTrace;
    bool operator==(const Lighting&) const = default;
};

// What the fast renderer leaves out of `lighting` (it lights with the shading's key and fill and
// has a pinhole camera): a sentence for the user, empty when nothing is left out. A still that
// looks different from the path-traced one must say why, not stay silent.
std::string lightingIgnoredByFastMode(const Lighting& lighting);

// The sensor height a thin lens's f-stop is measured against: full frame, in world units taken
// as metres (radius = focal length / (2 N), focal length from the field of view and this height).
inline constexpr double kSensorHeight = 0.024;
double apertureRadiusFromFStop(double fStop, double fovYDegrees);

// Readers of the preset sections; errors name the file, the field path and the reason. `camera`
// reads the lens fields ("aperture", "fStop", "focusDistance", "blades") of the "camera" section.
void readLens(FieldReader& camera, const Camera& c, ThinLens& lens);
std::vector<Light> parseLights(const ReadContext& context, const nlohmann::json& j);
EnvironmentSettings parseEnvironment(const ReadContext& context, const nlohmann::json& j);
PathTraceSettings parsePathTrace(const ReadContext& context, const nlohmann::json& j);

// "lights", "environment" and "pathTrace": the top-level sections these readers own.
bool isLightingSection(const std::string& key);

// Writers: only what differs from defaults; each adds its section(s) to `preset` (none when all
// are defaults, so a preset without lighting saves as before).
void writeLighting(const Lighting& lighting, nlohmann::json& preset);

}  // namespace fraktal
