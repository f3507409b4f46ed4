// The `fraktal` subcommands. Each adds itself to the CLI11 app and sets `action` when chosen.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace fraktal::cli {

using Action = std::function<int()>;

void addCheckCommand(CLI::App& app, Action& action);

}  // namespace fraktal::cli
