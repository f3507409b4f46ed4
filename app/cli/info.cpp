// `fraktal info FILE.exr`: size, channels, colour space and the embedded preset of a still.
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "core/image/exr_writer.hpp"
#include "core/preset.hpp"

namespace fraktal::cli {

void addInfoCommand(CLI::App& app, Action& action) {
    auto file = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("info", "Print an EXR's header and the fraktal preset embedded in it");
    cmd->add_option("file", *file, "EXR written by fraktal render")->required();
    cmd->callback([&action, file] {
        action = [file] {
            std::error_code ec;
            if (!std::filesystem::is_regular_file(*file, ec)) throw PresetError(*file, "", "no such file");
            std::fputs(describeExr(*file).c_str(), stdout);
            return 0;
        };
    });
}

}  // namespace fraktal::cli
