#include "core/lighting.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "core/preset.hpp"

namespace fraktal {

double focusDistanceOf(const ThinLens& lens, const Camera& camera) {
    return lens.focusDistance > 0.0 ? lens.focusDistance : length(camera.target - camera.position);
}

using nlohmann::json;

namespace {

Light parseLight(const ReadContext& context, const json& j, const std::string& path) {
    FieldReader r(context, j, path);
    Light l;
    const std::string type = r.string("type", kLightTypeNames[0].name, 32);
    std::string known;
    bool found = false;
    for (const LightTypeNames& n : kLightTypeNames) {
        for (const char* name : {n.name, n.alias}) {
            if (!name) continue;
            known += (known.empty() ? "" : ", ") + std::string(name);
            if (type == name && !found) {
                l.type = n.type;
                found = true;
            }
        }
    }
    if (!found) r.fail("unknown light type '" + type + "' (known: " + known + ")", "type");
    if (r.context().log) {
        std::vector<std::string> names;
        for (const LightTypeNames& n : kLightTypeNames) names.emplace_back(n.name);
        r.noteChoice("type", type, std::move(names));
    }
    l.enabled = r.boolean("enabled", true);
    l.color = r.vector<3>("color", l.color, 0.0, 1e4);
    l.intensity = r.number("intensity", l.intensity, 0.0, 1e9);
    if (r.has("size")) {
        const double size = r.checkNumber(r.at("size"), r.child("size"), -1e300, 1e300);
        if (size < 0.0)
            r.fail("a light's size must not be negative (found " + FieldReader::formatNumber(size) + ")", "size");
        l.size = size;
    }
    if (l.type == LightType::Directional) {
        l.direction = r.vector<3>("direction", l.direction, -1e3, 1e3);
        if (length(l.direction) < 1e-9) r.fail("a direction must not be zero", "direction");
        if (l.size > 45.0) r.fail("a directional light's angular radius is at most 45 degrees", "size");
    } else {
        l.position = r.vector<3>("position", l.position, -1e4, 1e4);
    }
    if (l.type == LightType::Rect) {
        if (!r.has("size")) l.size = 1.0;
        l.height = r.number("height", l.height, 0.0, 1e4);
        l.normal = r.vector<3>("normal", l.normal, -1e3, 1e3);
        l.up = r.vector<3>("up", l.up, -1e3, 1e3);
        if (length(l.normal) < 1e-9) r.fail("a direction must not be zero", "normal");
        if (length(glm::cross(normalize(l.normal), l.up)) < 1e-6) r.fail("up is zero or parallel to the normal", "up");
        if (l.size <= 0.0 || l.height <= 0.0) r.fail("a rect light needs a positive size and height", "size");
    }
    r.finish();
    return l;
}

}  // namespace

static_assert(
    [] {
        for (size_t i = 0; i < std::size(kLightTypeNames); ++i)
            if (kLightTypeNames[i].type != LightType(i)) return false;
        return std::size(kLightTypeNames) == size_t(LightType::Rect) + 1;
    }(),
    "kLightTypeNames lists every LightType in the enum's order");

const LightTypeNames& lightTypeNames(LightType type) { return kLightTypeNames[size_t(type)]; }

double apertureRadiusFromFStop(double fStop, double fovYDegrees) {
    const double focalLength = 0.5 * kSensorHeight / std::tan(0.5 * fovYDegrees * 3.14159265358979323846 / 180.0);
    return focalLength / (2.0 * fStop);
}

void readLens(FieldReader& r, const Camera& c, ThinLens& lens) {
    if (r.has("aperture") && r.has("fStop")) r.fail("give either aperture (a radius) or fStop, not both", "fStop");
    if (r.has("aperture")) {
        lens.apertureRadius = r.number("aperture", 0.0, 0.0, 1e3);
        if (lens.apertureRadius == 0.0)
            r.fail("an aperture of 0 gives no depth of field; remove the field for a pinhole camera", "aperture");
    }
    if (r.has("fStop")) lens.apertureRadius = apertureRadiusFromFStop(r.number("fStop", 8.0, 0.5, 1024.0), c.fovY);
    lens.focusDistance = r.number("focusDistance", 0.0, 0.0, 1e5);
    if (r.has("focusDistance") && lens.focusDistance == 0.0)
        r.fail("the focus distance must be positive (leave it out to focus on the target)", "focusDistance");
    lens.blades = r.integer("blades", 0, 0, 16);
    if (lens.blades == 1 || lens.blades == 2) r.fail("an aperture has 0 (round) or 3 to 16 blades", "blades");
    if (!lens.enabled() && (r.has("focusDistance") || r.has("blades")))
        r.fail("focusDistance and blades need an aperture or fStop (depth of field is off without one)",
               r.has("focusDistance") ? "focusDistance" : "blades");
}

std::vector<Light> parseLights(const ReadContext& context, const json& j) {
    if (!j.is_array())
        throw PresetError(context.file, "lights", "expected an array of lights, found " + FieldReader::typeName(j));
    if (j.size() > size_t(kMaxLights))
        throw PresetError(context.file, "lights", "at most " + std::to_string(kMaxLights) + " lights");
    std::vector<Light> lights;
    for (size_t i = 0; i < j.size(); ++i)
        lights.push_back(parseLight(context, j[i], "lights[" + std::to_string(i) + "]"));
    return lights;
}

EnvironmentSettings parseEnvironment(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "environment");
    EnvironmentSettings e;
    e.map = r.string("map", "", 4096);
    if (e.map.empty()) r.fail("missing required field (the path of an equirectangular EXR)", "map");
    const std::string ext = e.map.size() >= 4 ? e.map.substr(e.map.size() - 4) : "";
    if (ext != ".exr" && ext != ".EXR")
        r.fail("'" + e.map + "' is not an OpenEXR file (.exr); the environment must be a scene-linear EXR", "map");
    e.colorSpace = r.string("colorSpace", e.colorSpace, 256);
    e.intensity = r.number("intensity", e.intensity, 0.0, 1e6);
    e.rotation = r.number("rotation", e.rotation, -360.0, 360.0);
    e.visible = r.boolean("visible", e.visible);
    r.finish();
    return e;
}

PathTraceSettings parsePathTrace(const ReadContext& context, const json& j) {
    FieldReader r(context, j, "pathTrace");
    PathTraceSettings p;
    p.bounces = r.integer("bounces", p.bounces, 0, 16);
    p.roughness = r.number("roughness", p.roughness, 0.02, 1.0);
    p.specular = r.number("specular", p.specular, 0.0, 1.0);
    p.emission = r.number("emission", p.emission, 0.0, 1e4);
    r.finish();
    return p;
}

bool isLightingSection(const std::string& key) { return key == "lights" || key == "environment" || key == "pathTrace"; }

void writeLighting(const Lighting& l, json& preset) {
    if (l.lens.enabled()) {
        preset["camera"]["aperture"] = l.lens.apertureRadius;
        if (l.lens.focusDistance > 0.0) preset["camera"]["focusDistance"] = l.lens.focusDistance;
        if (l.lens.blades > 0) preset["camera"]["blades"] = l.lens.blades;
    }
    if (!l.lights.empty()) {
        json lights = json::array();
        const Light d;
        for (const Light& light : l.lights) {
            json o = json::object();
            o["type"] = lightTypeNames(light.type).name;
            if (!light.enabled) o["enabled"] = false;
            if (light.color != d.color) o["color"] = vecJson(light.color);
            if (light.intensity != d.intensity) o["intensity"] = light.intensity;
            if (light.type == LightType::Directional) {
                o["direction"] = vecJson(light.direction);
            } else {
                o["position"] = vecJson(light.position);
            }
            if (light.type == LightType::Rect) {
                o["height"] = light.height;
                o["normal"] = vecJson(light.normal);
                o["up"] = vecJson(light.up);
            }
            if (light.size != 0.0 || light.type == LightType::Rect) o["size"] = light.size;
            lights.push_back(o);
        }
        preset["lights"] = lights;
    }
    if (l.environment.active()) {
        const EnvironmentSettings d;
        json e = json::object();
        e["map"] = l.environment.map;
        if (l.environment.colorSpace != d.colorSpace) e["colorSpace"] = l.environment.colorSpace;
        if (l.environment.intensity != d.intensity) e["intensity"] = l.environment.intensity;
        if (l.environment.rotation != d.rotation) e["rotation"] = l.environment.rotation;
        if (l.environment.visible != d.visible) e["visible"] = l.environment.visible;
        preset["environment"] = e;
    }
    const PathTraceSettings d;
    json p = json::object();
    if (l.pathTrace.bounces != d.bounces) p["bounces"] = l.pathTrace.bounces;
    if (l.pathTrace.roughness != d.roughness) p["roughness"] = l.pathTrace.roughness;
    if (l.pathTrace.specular != d.specular) p["specular"] = l.pathTrace.specular;
    if (l.pathTrace.emission != d.emission) p["emission"] = l.pathTrace.emission;
    if (!p.empty()) preset["pathTrace"] = p;
}

std::string lightingIgnoredByFastMode(const Lighting& lighting) {
    std::vector<std::string> parts;
    const size_t on =
        size_t(std::count_if(lighting.lights.begin(), lighting.lights.end(), [](const Light& l) { return l.enabled; }));
    if (on > 0) parts.push_back(std::to_string(on) + (on == 1 ? " light" : " lights"));
    if (lighting.environment.active()) parts.push_back("the environment map");
    if (parts.empty()) return "";
    std::string list = parts[0];
    for (size_t i = 1; i < parts.size(); ++i) list += (i + 1 == parts.size() ? " and " : ", ") + parts[i];
    return "the preset's " + list + (parts.size() == 1 && on <= 1 ? " applies" : " apply") +
           " only with --mode path; the fast renderer lights with the shading's key and fill lights";
}

}  // namespace fraktal
