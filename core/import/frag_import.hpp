// What a Fragmentarium / FragM frag means as a fraktal scene (parsing is core/import/frag_file):
// its `float DE(vec3)` with the helper functions, globals and #define lines it reaches becomes
// one whole-DE estimator (core/whole_de.hpp) carried in the preset; the uniforms it reads become
// the estimator's parameters (ranges, defaults, tooltips, groups); the chosen #preset's values
// apply; 3D.frag's camera (Eye, Target, Up, FOV) and DE-Raytracer's Detail, FudgeFactor and
// MaxRaySteps map onto fraktal's camera and render settings, and DE-Raytracer's lights, AO, fog,
// background and orbit-trap colours onto its shading (core/import/frag_shading).
//
// Faithful, never silently different, as the Mandelbulber2 import: a frag that fraktal cannot
// draw at all (no DE, a Brute-Raytracer `inside()` frag, a texture read by the DE) is refused
// with the reason; what the preset cannot carry (the DE reading `time`, a #buffer pass, a
// uniform of a kind fraktal's parameters lack) is listed in `unsupported`, and the caller refuses
// the file unless asked to be lenient (then `time` reads 0, as on FragM's first frame, and such
// a uniform keeps its value as a constant).
// Reference: ../shared/reference/fragmentarium-frag.md.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/import/fract_import.hpp"
#include "core/import/frag_file.hpp"
#include "core/preset.hpp"

namespace fraktal::frag {

using mb2::ImportItem;

// How to read a frag for an import: fraktal's built-in includes (core/import/frag_builtins)
// before any folder, then `includeDirs` for the others.
FragOptions importParseOptions(const std::vector<std::filesystem::path>& includeDirs);

struct FragImportOptions {
    std::string presetName = {};  // "" : FragM's choice (the first "default" in sorted order), else the first preset
};

struct FragImport {
    Preset preset;
    std::string presetUsed;                // the #preset applied ("" when the file has none)
    std::vector<ImportItem> unsupported;   // the preset differs from the frag here
    std::vector<ImportItem> approximated;  // the look is matched approximately here
    // What the raytracer draws beside the DE (DE-Raytracer's floor, as a plane object), and how far
    // from the eye FragM marches to it (MaxDistance). They join the formula after its step is
    // measured (core/scene/scene_import.cpp): the step and the fitted bound are the DE's alone.
    std::vector<SceneObject> objects;
    double objectReach = 0.0;
    // DE-Raytracer's AO reach and fog extinction in world units (0: fraktal's default share of the
    // bound, no fog), which the preset holds per bound radius (holdShadingLengths).
    double aoReach = 0.0;
    double fogPerUnit = 0.0;
    bool faithful() const { return unsupported.empty(); }
};

// Throws PresetError naming the file for a frag that has no distance estimate fraktal can use,
// and for a --preset name the file does not have (listing those it has).
FragImport importFrag(const FragFile& file, const FragImportOptions& options = {});

// Sets the preset's AO distance and fog density from aoReach and fogPerUnit for its present bound
// radius: again after the caller fits the bound, so that FragM's lengths stay as they were.
void holdShadingLengths(FragImport& result);

// The preset's description: where it came from, and what was dropped or approximated.
std::string importDescription(const FragFile& file, const FragImport& result);

}  // namespace fraktal::frag
