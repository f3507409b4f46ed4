// The Lights tab's edits of a scene's Lighting (core/lighting.hpp) and the click-to-focus
// rule, without ImGui: adding, duplicating and removing lights within kMaxLights, checking an
// environment map before the document takes it, and the lens focus distance of the surface under
// the cursor. The tab (lights_panel.cpp) draws them; the panel's own state lives here too.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "app/editor/input/fly_speed.hpp"
#include "core/camera.hpp"
#include "core/formula.hpp"
#include "core/lighting.hpp"
#include "core/render_settings.hpp"

namespace fraktal::editor {

// What the Lights tab keeps between frames (owned by EditorState).
struct LightsPanel {
    int selected = 0;       // the light whose settings show
    std::string mapField;   // the environment map path being typed
    std::string syncedMap;  // the document's map that mapField last showed
    std::string message;    // why the last edit was refused (a full list, a bad map), or a pick's result
    bool messageIsError = false;
    bool pickFocus = false;  // the next left click in the viewport sets the focus distance
    // Window rectangles (x, y, w, h) of the tab's widgets as last drawn, by name, for the state
    // file (tests find the widgets there).
    std::map<std::string, std::array<float, 4>> widgets;
};

// A light of `type` where the default scene can see its effect: a directional light from above
// and to the side, a sphere light above the object, a rectangle facing down onto it.
Light newLight(LightType type);

// Appends a new light; refused (a message naming the limit, the list unchanged) at kMaxLights.
// Returns the message, empty on success.
std::string addLight(Lighting& lighting, LightType type);
// Inserts a copy of light `index` after it; refused at kMaxLights or for an index out of range.
std::string duplicateLight(Lighting& lighting, int index);
// Removes light `index`; false for an index out of range.
bool removeLight(Lighting& lighting, int index);

// Why `file` cannot be an environment map (missing, a folder, not an OpenEXR file, an unreadable
// header), or empty when it can. Reads only the header.
std::string environmentMapProblem(const std::filesystem::path& file);
// The "environment.map" value for a chosen file: relative to the preset's folder when the
// document has a file (as the preset format resolves it), else the absolute path.
std::string environmentMapValue(const std::filesystem::path& chosen, const std::filesystem::path& presetFile);

// The thin lens's focus distance of a point: its depth along the camera's view axis (ThinLens
// focuses the plane at that depth, not a sphere of that ray length).
double viewAxisDistance(const Camera& camera, const vec3& point);

// The first surface point along the ray from the camera through normalised device coordinates
// (ndcX, ndcY) of a view of `aspect` and `imageHeight` pixels, marched as the viewport marches
// (the CPU mirror of march.glsl with the render settings' detail and step limit) when the formula
// has a CPU body, else by sphere tracing `de` (the GPU probe). None: the ray reaches the sky.
std::optional<vec3> surfaceUnderCursor(const Formula& formula, const Camera& camera, const RenderSettings& render,
                                       const ShadingSettings& shading, const DistanceAt& de, double ndcX, double ndcY,
                                       double aspect, double imageHeight);

}  // namespace fraktal::editor
