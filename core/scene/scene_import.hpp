// Opening another program's scene file as a fraktal preset: a Mandelbulber2 .fract file or a
// Fragmentarium .frag through core/import (the mapping), then what follows any structure change
// here: the bound fitted to the object (a .fract) and the safe step measured (a frag's DE is GLSL
// alone, with no CPU twin: it is measured on a GL context the caller provides). The command line
// (`fraktal import`, `fraktal render FILE.fract`) and the editor (File > Open, a dropped file)
// share it.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/de_check.hpp"
#include "core/preset.hpp"

namespace fraktal {

struct SceneImportOptions {
    // Write the preset although the file uses what fraktal cannot express (listed in its
    // description); otherwise such a file is refused.
    bool lenient = false;
    // Measure the safe step factor (CPU: a fraction of a second to half a minute for 250
    // iterations), as `fraktal check` does; the bound is fitted either way. The editor measures it
    // itself, as after any structure change.
    bool measure = true;
    // A .frag: the #preset to apply ("" : FragM's own choice, its first "default" preset, else the
    // first), and the folders searched for includes that are neither next to the frag nor among
    // fraktal's built-in ones (a FragM install's Examples/Include).
    std::string fragPreset = {};
    std::vector<std::filesystem::path> includeDirs = {};
    // How a formula that only GLSL evaluates (a frag's DE) is sampled to measure its safe step: a
    // GL sampler (gl::GpuSampler) on a context the caller makes current, or null when it has none.
    // Without one a frag's FudgeFactor stays its step factor, unmeasured.
    std::function<std::unique_ptr<FormulaSampler>(const Formula&)> glslSampler = {};
};

struct ImportedScene {
    Preset preset;
    std::vector<std::string> unsupported;   // "slot 2 (mandelbulb_power2): ..." (lenient only)
    std::vector<std::string> approximated;  // what only looks different
    // A .frag: the #preset blocks one can apply (FragM's preset list: every named preset of the
    // file and its includes, once each, keyframes left out), and the one this import applied.
    std::vector<std::string> presetChoices = {};
    std::string presetUsed = {};
};

// Whether the file is opened by import rather than as a preset (by its extension: .fract, .frag).
bool isImportedSceneFile(const std::filesystem::path& path);
// The program an imported scene file comes from, for messages: "Mandelbulber2" (.fract),
// "Fragmentarium" (.frag); empty for any other file.
std::string importedSceneProgram(const std::filesystem::path& path);

// Throws PresetError: for a file it cannot read, and (unless lenient) for a file that uses what
// fraktal cannot express, listing every such thing with its slot.
ImportedScene importSceneFile(const std::filesystem::path& path, const SceneImportOptions& options = {});

// A preset or an imported scene: what `fraktal render` and `fraktal check` open. Imports are
// strict here (no --lenient); `glslSampler` as in SceneImportOptions.
Preset loadSceneFile(const std::filesystem::path& path,
                     const std::function<std::unique_ptr<FormulaSampler>(const Formula&)>& glslSampler = {});

}  // namespace fraktal
