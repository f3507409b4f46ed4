// `fraktal merge PART.exr... -o OUT.exr`: the parts of a still (`fraktal render --part i/n`) joined.
#include <cstdio>

#include "cli/commands.hpp"
#include "core/image/exr_merge.hpp"

namespace fraktal::cli {

void addMergeCommand(CLI::App& app, Action& action) {
    auto parts = std::make_shared<std::vector<std::string>>();
    auto output = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand("merge", "Join the parts of a still rendered with --part i/n into one EXR");
    cmd->add_option("parts", *parts, "The part EXRs, in any order")->required();
    cmd->add_option("-o,--output", *output, "Output EXR")->required();
    cmd->callback([&action, parts, output] {
        action = [parts, output] {
            mergeExrParts(std::vector<std::filesystem::path>(parts->begin(), parts->end()), *output);
            std::fprintf(stderr, "merged %zu parts into %s\n", parts->size(), output->c_str());
            return 0;
        };
    });
}

}  // namespace fraktal::cli
