#include "app/editor/document/lights_edits.hpp"

#include <ImfTestFile.h>

#include <algorithm>
#include <cmath>

#include "core/cpu_render/cpu_shading.hpp"
#include "core/shading_params.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

Light newLight(LightType type) {
    Light l;
    l.type = type;
    switch (type) {
        case LightType::Directional:
            l.size = 0.27;  // the sun's angular radius in degrees: soft-edged shadows
            break;
        case LightType::Sphere:
            l.position = vec3(1.5, 3.0, 1.5);
            l.size = 0.25;
            l.intensity = 10.0;  // radiant intensity: at distance ~3.5 about the directional default
            break;
        case LightType::Rect:
            l.position = vec3(0.0, 3.0, 0.0);
            l.size = 2.0;
            l.height = 2.0;
            l.intensity = 2.0;
            break;
    }
    return l;
}

namespace {
std::string fullListMessage() {
    return "A scene has at most " + std::to_string(kMaxLights) + " lights (the path tracer's limit); remove one first.";
}
bool inRange(const Lighting& lighting, int index) { return index >= 0 && size_t(index) < lighting.lights.size(); }
}  // namespace

std::string addLight(Lighting& lighting, LightType type) {
    if (lighting.lights.size() >= size_t(kMaxLights)) return fullListMessage();
    lighting.lights.push_back(newLight(type));
    return "";
}

std::string duplicateLight(Lighting& lighting, int index) {
    if (!inRange(lighting, index)) return "No light " + std::to_string(index + 1) + " to duplicate.";
    if (lighting.lights.size() >= size_t(kMaxLights)) return fullListMessage();
    const Light copy = lighting.lights[size_t(index)];
    lighting.lights.insert(lighting.lights.begin() + index + 1, copy);
    return "";
}

bool removeLight(Lighting& lighting, int index) {
    if (!inRange(lighting, index)) return false;
    lighting.lights.erase(lighting.lights.begin() + index);
    return true;
}

std::string environmentMapProblem(const fs::path& file) {
    std::error_code ec;
    if (file.empty()) return "No file given.";
    if (!fs::exists(file, ec)) return "'" + file.string() + "' does not exist.";
    if (!fs::is_regular_file(file, ec)) return "'" + file.string() + "' is not a file.";
    // The preset reader takes only the .exr / .EXR extension (core/lighting.cpp).
    const std::string ext = file.extension().string();
    if (ext != ".exr" && ext != ".EXR")
        return "'" + file.filename().string() +
               "' is not an OpenEXR file (.exr); the environment must be a scene-linear EXR.";
    bool tiled = false, deep = false, multiPart = false;
    if (!Imf::isOpenExrFile(file.c_str(), tiled, deep, multiPart))
        return "'" + file.filename().string() + "' has an .exr name but is not an OpenEXR file.";
    if (deep) return "'" + file.filename().string() + "' is a deep EXR; the environment needs an RGB image.";
    return "";
}

std::string environmentMapValue(const fs::path& chosen, const fs::path& presetFile) {
    const fs::path file = fs::absolute(chosen).lexically_normal();
    if (presetFile.empty()) return file.string();
    const fs::path folder = fs::absolute(presetFile).parent_path().lexically_normal();
    const fs::path relative = file.lexically_relative(folder);
    return relative.empty() ? file.string() : relative.string();
}

double viewAxisDistance(const Camera& camera, const vec3& point) {
    return dot(point - camera.position, camera.basis().forward);
}

std::optional<vec3> surfaceUnderCursor(const Formula& formula, const Camera& camera, const RenderSettings& render,
                                       const ShadingSettings& shading, const DistanceAt& de, double ndcX, double ndcY,
                                       double aspect, double imageHeight) {
    const vec3 ro = camera.position;
    const vec3 rd = camera.rayDirection(ndcX, ndcY, aspect);
    const double pixelAngle = camera.pixelAngle(std::max(imageHeight, 1.0));
    const ShadingParams params = resolveShading(shading, render, formula);
    const cpu::Scene scene{formula, params};
    double tStart = 0.0, tEnd = 0.0;
    if (!cpu::clipCameraRay(scene, ro, rd, tStart, tEnd)) return std::nullopt;
    if (formula.cpuEvaluable()) {
        // The viewport's own marcher and hit test (cpu_renderer.cpp), so the focus lands where the
        // image shows the surface.
        double deEvals = 0.0;
        cpu::MarchState s = cpu::marchStart(scene, tStart);
        cpu::marchRay(scene, ro, rd, tEnd, pixelAngle, render.maxSteps, s, deEvals);
        const bool hit = cpu::countsAsHit(scene, s, pixelAngle);
        if (!hit) return std::nullopt;
        return ro + rd * s.t;
    }
    // Custom GLSL has no CPU body: the caller's DE (the GPU probe), plainly sphere traced.
    cpu::MarchRule rule;
    rule.coneAngle = pixelAngle * params.detail;
    const std::optional<double> t = traceDistance(de, ro, rd, tStart, tEnd, rule, render.maxSteps);
    if (!t) return std::nullopt;
    return ro + rd * *t;
}

}  // namespace fraktal::editor
