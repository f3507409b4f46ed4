// The `fraktal` subcommands. Each adds itself to the CLI11 app and sets `action` when chosen.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "core/de_check.hpp"
#include "core/preset.hpp"

namespace fraktal::cli {

using Action = std::function<int()>;

void addCheckCommand(CLI::App& app, Action& action);
void addEditCommand(CLI::App& app, Action& action);
// What `fraktal` with no subcommand does: open the editor on presets/mandelbulb.json.
Action defaultEditorAction();
void addRenderCommand(CLI::App& app, Action& action);
void addInfoCommand(CLI::App& app, Action& action);
void addBenchViewportCommand(CLI::App& app, Action& action);
void addMergeCommand(CLI::App& app, Action& action);
void addEncodeCommand(CLI::App& app, Action& action);
void addFarmCommand(CLI::App& app, Action& action);
void addImportCommand(CLI::App& app, Action& action);
void addMeshCommand(CLI::App& app, Action& action);

// Samples a formula that only GLSL evaluates (a frag's DE) on a headless GL context made at the
// first call and kept while the returned function lives, so that an import measures its safe step
// (SceneImportOptions::glslSampler); gives null where no GL context can be made.
std::function<std::unique_ptr<FormulaSampler>(const Formula&)> headlessGlslSampler();

// A scene file (preset, .fract or .frag) as loaded, or its animation's `frame` (`--frame N` of check and
// mesh); a frame on a still or outside the animation is an error naming the file.
Preset sceneAtFrame(const std::string& file, std::optional<int> frame);

}  // namespace fraktal::cli
