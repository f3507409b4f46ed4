// `fraktal info FILE.exr`: size, channels, colour space and the embedded preset of a still (3D
// or 2D).
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "core/image/exr_writer.hpp"
#include "core/plane/plane_still.hpp"
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
            std::string text = describeExr(*file);
            if (const std::optional<std::string> plane = readExrPlanePreset(*file)) {
                // describeExr knows the 3D still's attribute only; a 2D still's preset is
                // under its own (core/plane/plane_still.hpp), so its "none" line is wrong here.
                const std::string none = "no embedded fraktal preset\n";
                if (const size_t at = text.rfind(none); at != std::string::npos) text.erase(at, none.size());
                text += std::string("2D preset (") + kExrPlanePresetAttribute + "):\n" + *plane;
            }
            std::fputs(text.c_str(), stdout);
            return 0;
        };
    });
}

}  // namespace fraktal::cli
