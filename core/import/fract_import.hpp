// What a Mandelbulber2 settings file means as a fraktal scene: the formula slots and hybrid
// sequence as a node list, each formula's parameters (with Mandelbulber2's own defaults for what
// the file leaves out), N and the bailout, the DE function as a closing estimator, the camera,
// the main light, background, fog, ambient occlusion and depth of field.
//
// Faithful, never silently different: what fraktal cannot express (a formula, a formula's option,
// a setting that changes the shape or the view) is listed in `unsupported`, each item with where
// it is ("slot 2 (mandelbulb_power2)", "main"). The caller refuses such a file unless asked to be
// lenient. What only changes the look (the colour gradient, the lights beyond the main one) is
// matched as closely as fraktal's shading allows and listed in `approximated`.
// Formula correspondences: ../shared/reference/mandelbulber2-fract.md, T5, T6 and Notes 2-5.
#pragma once

#include <string>
#include <vector>

#include "core/import/fract_file.hpp"
#include "core/preset.hpp"

namespace fraktal::mb2 {

struct ImportItem {
    std::string where;  // "slot 1 (kaleidoscopic_ifs)", "main", "camera", ...
    std::string what;   // the parameter or feature and why, in words

    std::string text() const { return where + ": " + what; }
};

struct FractImport {
    Preset preset;
    std::vector<ImportItem> unsupported;   // the preset differs from the file here
    std::vector<ImportItem> approximated;  // the look is matched approximately here
    std::vector<std::string> formulas;     // the slots that run, in order ("mandelbox", ...)

    bool faithful() const { return unsupported.empty(); }
};

// The scene the file describes. Throws PresetError for a value it cannot read (naming the file,
// section, parameter and line); everything fraktal cannot express is in `unsupported`, not thrown.
// The preset's formula still has the file's factor and a bound from view_distance_max: the app
// fits the bound and measures the safe step as after any structure change.
FractImport importFract(const FractFile& file);

// The preset's description for an import: where it came from, and what was dropped or
// approximated.
std::string importDescription(const FractFile& file, const FractImport& result);

// Mandelbulber2's name for a formula id ("mandelbox" for 8), or "formula N" for one it does not
// know.
std::string formulaName(int id);

}  // namespace fraktal::mb2
