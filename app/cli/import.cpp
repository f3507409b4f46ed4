// `fraktal import FILE.fract|FILE.frag [-o PRESET.json] [--lenient] [--preset NAME] [--include-dir DIR]`:
// a Mandelbulber2 settings file or a Fragmentarium frag as a fraktal preset
// (core/scene/scene_import.hpp). A file that uses what fraktal cannot express is refused, each
// such thing named with where it is, and nothing is written; --lenient writes the preset anyway
// and lists what was dropped in its description.
#include <algorithm>
#include <cstdio>
#include <memory>

#include "cli/commands.hpp"
#include "core/gl/context.hpp"
#include "core/gl/de_probe.hpp"
#include "core/import/frag_file.hpp"
#include "core/scene/scene_import.hpp"

namespace fraktal::cli {

namespace {
struct ImportArgs {
    std::string input;
    std::string output;
    bool lenient = false;
    bool quiet = false;
    std::string preset;
    std::vector<std::string> includeDirs;
};
}  // namespace

std::function<std::unique_ptr<FormulaSampler>(const Formula&)> headlessGlslSampler() {
    auto context = std::make_shared<std::unique_ptr<gl::HeadlessContext>>();
    return [context](const Formula& f) -> std::unique_ptr<FormulaSampler> {
        try {
            if (!*context) *context = gl::HeadlessContext::create();
        } catch (const std::exception& e) {
            std::fprintf(stderr, "the step factor is not measured: %s\n", e.what());
            return nullptr;
        }
        return std::make_unique<gl::GpuSampler>(f);
    };
}

void addImportCommand(CLI::App& app, Action& action) {
    auto a = std::make_shared<ImportArgs>();
    CLI::App* cmd = app.add_subcommand(
        "import", "Convert a Mandelbulber2 settings file (.fract) or a Fragmentarium frag (.frag) to a fraktal preset");
    cmd->add_option("file", a->input, "Mandelbulber2 settings file (v2 format) or Fragmentarium/FragM frag")
        ->required();
    cmd->add_option("--preset", a->preset,
                    "A frag's #preset to apply (default: its first preset named like \"default\", else its first)");
    cmd->add_option("--include-dir", a->includeDirs,
                    "A folder searched for a frag's includes that fraktal does not provide itself (repeatable)");
    cmd->add_option("-o,--output", a->output, "Preset to write (default: the file's name with .json, here)");
    cmd->add_flag("--lenient", a->lenient,
                  "Write the preset even where fraktal cannot express part of the file (listed in its description)");
    cmd->add_flag("-q,--quiet", a->quiet, "Print only errors");
    cmd->callback([&action, a] {
        action = [a] {
            std::error_code ec;
            if (!std::filesystem::is_regular_file(a->input, ec)) throw PresetError(a->input, "", "no such file");
            if (!isImportedSceneFile(a->input))
                throw PresetError(a->input, "",
                                  "neither a Mandelbulber2 settings file nor a Fragmentarium frag (expected the "
                                  "extension .fract or .frag)");
            if (!a->preset.empty() && !frag::isFragPath(a->input))
                throw PresetError(a->input, "", "--preset names a frag's #preset; this is not a .frag");
            SceneImportOptions options{.lenient = a->lenient};
            options.fragPreset = a->preset;
            for (const std::string& dir : a->includeDirs) options.includeDirs.emplace_back(dir);
            options.glslSampler = headlessGlslSampler();
            const ImportedScene scene = importSceneFile(a->input, options);
            const std::filesystem::path output = a->output.empty()
                                                     ? std::filesystem::path(a->input).stem().concat(".json")
                                                     : std::filesystem::path(a->output);
            savePresetFile(output, scene.preset);
            if (!a->quiet) {
                const Formula& f = scene.preset.formula;
                if (f.estimator.block->wholeDE) {
                    std::printf(
                        "%s: whole DE '%s' (%zu parameters, %zu lines of GLSL), step factor %.3f\n",
                        output.string().c_str(), std::string(f.estimator.block->id).c_str(),
                        f.estimator.block->params.size(),
                        size_t(std::count(f.estimator.block->glsl.begin(), f.estimator.block->glsl.end(), '\n')),
                        f.deFactor);
                    for (const std::string& item : scene.unsupported) std::printf("  dropped: %s\n", item.c_str());
                    for (const std::string& item : scene.approximated)
                        std::printf("  approximated: %s\n", item.c_str());
                    return 0;
                }
                std::printf("%s: %zu nodes, %s, %d iterations, bailout %g, bound %.3g, step factor %.3f\n",
                            output.string().c_str(), f.nodes.size(), std::string(f.estimator.block->id).c_str(),
                            f.iterations, f.bailout, f.boundRadius, f.deFactor);
                for (size_t i = 0; i < f.fractals.size(); ++i) {
                    const Formula& c = f.fractals[i].formula;
                    std::printf("  fractal %zu (%s): %zu nodes, %s, %d iterations, bailout %g, step factor %.3f\n",
                                i + 2, std::string(kObjectOperationNames[int(f.fractals[i].operation)]).c_str(),
                                c.nodes.size(), std::string(c.estimator.block->id).c_str(), c.iterations, c.bailout,
                                c.deFactor);
                }
                for (const std::string& item : scene.unsupported) std::printf("  dropped: %s\n", item.c_str());
                for (const std::string& item : scene.approximated) std::printf("  approximated: %s\n", item.c_str());
            }
            return 0;
        };
    });
}

}  // namespace fraktal::cli
