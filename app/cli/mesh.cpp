// `fraktal mesh PRESET -o OUT.{vdb,ply,obj,stl,glb}`: the preset's fractal as a sparse
// narrow-band level set (OpenVDB) and a closed, manifold triangle mesh for printing
// (core/mesh/mesh_formula.hpp); `--frames A-B -o out/mesh_####.ply` meshes an animation's frames.
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <regex>

#include "cli/cancel.hpp"
#include "cli/commands.hpp"
#include "core/anim/sequence.hpp"
#include "core/atomic_file.hpp"
#include "core/gl/context.hpp"
#include "core/gl/de_probe.hpp"
#include "core/mesh/mesh_file.hpp"
#include "core/mesh/mesh_formula.hpp"
#include "core/plane/plane_preset.hpp"
#include "core/preset.hpp"
#include "core/scene/scene_import.hpp"

namespace fraktal::cli {

namespace {

struct MeshOptions {
    std::string preset;
    std::string output;
    int resolution = 256;
    std::optional<double> voxel;
    std::vector<double> box;  // --box X0,Y0,Z0,X1,Y1,Z1
    std::optional<int> frame;
    std::string frames;  // --frames A-B[:STEP]
    double simplify = 0.0;
    std::string printSize;
    int threads = 0;
    bool removeCavities = false;
    double minThickness = 0.0;
    bool noColor = false;
    std::string device = "auto";
};

// "100mm", "10cm", "0.1m", "4in" or a bare number of millimetres, in millimetres.
double parsePrintSize(const std::string& text) {
    static const std::regex form(R"(^\s*([0-9]*\.?[0-9]+(?:[eE][-+]?[0-9]+)?)\s*(mm|cm|m|in)?\s*$)");
    std::smatch m;
    if (!std::regex_match(text, m, form))
        throw std::runtime_error("--print-size \"" + text + "\": not a size (a number with mm, cm, m or in: 100mm)");
    const double value = std::stod(m[1].str());
    const std::string unit = m[2].str();
    const double mm = value * (unit == "cm" ? 10.0 : unit == "m" ? 1000.0 : unit == "in" ? 25.4 : 1.0);
    if (!(mm > 0.0)) throw std::runtime_error("--print-size \"" + text + "\": the size must be positive");
    return mm;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A bar on a terminal; on a pipe (the editor's export, logs) a line per 5 % or new stage:
// "progress: sampling (42%)", which the editor's export reads.
struct MeshProgressPrinter {
    bool tty = ::isatty(STDERR_FILENO) != 0;
    std::string frameLabel;  // "frame 3/10: " in a sequence
    std::string lastStage;
    int lastPercent = -1;
    void operator()(const char* stage, double done) {
        const int percent = int(std::clamp(done, 0.0, 1.0) * 100.0);
        if (tty) {
            std::fprintf(stderr, "\r%s%-10s %3d%%   ", frameLabel.c_str(), stage, percent);
        } else if (stage != lastStage || percent >= lastPercent + 5) {
            std::fprintf(stderr, "progress: %s%s (%d%%)\n", frameLabel.c_str(), stage, percent);
        } else {
            return;
        }
        lastStage = stage;
        lastPercent = percent;
        std::fflush(stderr);
    }
    void finish() {
        if (tty && lastPercent >= 0) std::fputc('\n', stderr);
        lastPercent = -1;
        lastStage.clear();
    }
};

// The sampler the mesher estimates with: the GL probe on a headless context (the renderer's own
// GLSL, in single precision; on llvmpipe with two cores it meshes the Mandelbulb at 256^3 2.3x
// faster than the CPU path), or the CPU's (double precision, every core). auto takes the GL one
// when a context can be made, and the CPU otherwise, unless custom GLSL blocks need GL; and the
// CPU for a lattice finer than single precision resolves (a voxel under 1e-5 of the coordinates'
// size, about 80 steps of a float: a deep detail through --box).
std::unique_ptr<FormulaSampler> samplerFor(const MeshOptions& o, const Formula& f, const mesh::GridLayout& layout,
                                           std::unique_ptr<gl::HeadlessContext>& context) {
    const vec3 farCorner =
        glm::max(glm::abs(layout.minCorner), glm::abs(layout.minCorner + layout.voxel * double(layout.voxelsAcross)));
    const bool tooFineForFloats = layout.voxel < 1e-5 * std::max(farCorner.x, std::max(farCorner.y, farCorner.z));
    if (o.device == "cpu" || (o.device == "auto" && tooFineForFloats && f.cpuEvaluable())) {
        if (!f.cpuEvaluable())
            throw std::runtime_error(o.preset + ": custom GLSL blocks have no CPU version: mesh with --device gpu");
        return std::make_unique<CpuSampler>(f);
    }
    if (!context) {
        try {
            context = gl::HeadlessContext::create();
        } catch (const std::exception& e) {
            if (o.device == "gpu" || !f.cpuEvaluable())
                throw std::runtime_error(o.preset + ": " +
                                         (f.cpuEvaluable() ? "--device gpu" : "its custom GLSL blocks") +
                                         " need an OpenGL 4.5 context: " + e.what());
            std::fprintf(stderr, "no OpenGL context (%s): meshing on the CPU\n", e.what());
            return std::make_unique<CpuSampler>(f);
        }
    }
    return std::make_unique<gl::GpuSampler>(f);
}

// Meshes one preset (a still, or one frame of a sequence) into `output`.
void meshOne(const MeshOptions& o, std::optional<double> printMm, const Preset& preset,
             const std::filesystem::path& output, std::unique_ptr<gl::HeadlessContext>& context,
             MeshProgressPrinter& progress) {
    const std::string extension = output.extension().string();
    const bool vdb = extension == ".vdb";
    const Formula& f = preset.formula;
    mesh::MeshSettings settings;
    if (o.box.empty()) {
        settings.layout = o.voxel ? mesh::layoutByVoxel(f, *o.voxel) : mesh::layoutByResolution(f, o.resolution);
    } else {
        const mesh::Box box{vec3(o.box[0], o.box[1], o.box[2]), vec3(o.box[3], o.box[4], o.box[5])};
        settings.layout = o.voxel ? mesh::layoutOfBoxByVoxel(box, *o.voxel) : mesh::layoutOfBox(box, o.resolution);
        settings.clip = box;
    }
    const std::unique_ptr<FormulaSampler> sampler = samplerFor(o, f, settings.layout, context);
    settings.adaptivity = o.simplify;
    settings.threads = o.threads;
    settings.fillCavities = o.removeCavities;
    settings.minThickness = o.minThickness;
    if (!vdb && !o.noColor && mesh::carriesColors(extension))
        settings.colors = resolveShading(preset.shading, preset.render, f);
    settings.control.cancel = &cancelOnSignal();
    settings.control.progress = [&progress](const char* stage, double done) { progress(stage, done); };

    const auto start = std::chrono::steady_clock::now();
    mesh::FormulaVolume v = mesh::buildVolume(*sampler, settings);
    progress.finish();
    const int across = settings.layout.voxelsAcross;
    std::printf("%s%s: %d^3 voxels of %g, %zu of %lld bricks near the surface, on the %s\n",
                progress.frameLabel.c_str(), o.preset.c_str(), across, settings.layout.voxel, v.plan.bricks.size(),
                (long long)std::pow(double(settings.layout.bricksAcross()), 3.0),
                sampler->concurrent() ? "CPU" : "GPU");
    if (o.removeCavities) std::printf("cavities: %lld voxels filled\n", (long long)v.cavityVoxelsFilled);
    if (o.minThickness > 0.0)
        std::printf("thin parts (under %g): %lld voxels made solid\n", o.minThickness, (long long)v.thickenedVoxels);
    std::printf("level set: %lld active voxels, %.1f MiB (%.1fs)\n", (long long)v.volume.activeVoxels(),
                double(v.volume.memoryBytes()) / (1024.0 * 1024.0), secondsSince(start));
    if (vdb) {
        v.volume.writeVdb(output);
        std::printf("wrote %s (%.1fs)\n", output.c_str(), secondsSince(start));
        return;
    }
    mesh::TriangleMesh m = mesh::meshVolume(*sampler, v.volume, settings);
    progress.finish();
    if (m.triangles.empty())
        throw std::runtime_error(o.preset + ": no surface within the bound at this resolution (nothing written)");
    if (printMm) {
        const auto box = m.bounds();
        const vec3 extent = box[1] - box[0];
        m.transform(*printMm / std::max(extent.x, std::max(extent.y, extent.z)), vec3(0.0));
    }
    const auto box = m.bounds();
    const vec3 extent = box[1] - box[0];
    mesh::writeMesh(output, m);
    std::printf("wrote %s: %zu triangles, %zu vertices%s, volume %.6g, %.4g x %.4g x %.4g%s (%.1fs)\n", output.c_str(),
                m.triangles.size(), m.points.size(), m.colors.empty() ? "" : " coloured", m.enclosedVolume(), extent.x,
                extent.y, extent.z, printMm ? " mm" : "", secondsSince(start));
    std::fflush(stdout);
}

int runMesh(const MeshOptions& o) {
    const std::filesystem::path output(o.output);
    const std::string extension = output.extension().string();
    const bool vdb = extension == ".vdb";
    if (!vdb && !mesh::isMeshExtension(extension))
        throw std::runtime_error(o.output + ": unknown output format \"" + extension + "\" (one of .vdb, " +
                                 mesh::meshExtensions() + ")");
    std::optional<double> printMm;  // refused before any work
    if (!o.printSize.empty()) {
        if (vdb)
            throw std::runtime_error(o.output +
                                     ": --print-size scales a mesh; a .vdb keeps the preset's units (its voxel size)");
        printMm = parsePrintSize(o.printSize);
    }
    if (!o.box.empty() && !(o.box[3] > o.box[0] && o.box[4] > o.box[1] && o.box[5] > o.box[2]))
        throw std::runtime_error("--box: its high corner X1,Y1,Z1 must exceed its low corner X0,Y0,Z0 on every axis");
    if (isPlanePresetFile(o.preset))
        throw std::runtime_error(o.preset + ": a 2D preset has no surface to mesh (mesh a 3D preset)");
    // Ctrl+C from here on stops at the next batch, and leaves no file.
    cancelOnSignal();
    std::unique_ptr<gl::HeadlessContext> context;
    MeshProgressPrinter progress;
    try {
        if (o.frames.empty()) {
            // The output's folder is checked before any work (AtomicFile creates nothing yet).
            { AtomicFile check(output); }
            meshOne(o, printMm, sceneAtFrame(o.preset, o.frame), output, context, progress);
            return 0;
        }
        const Preset animated = loadSceneFile(o.preset, headlessGlslSampler());
        const FrameRange range = parseFrameRange(o.frames);
        checkFrameRangeWithin(range, animated.animation, o.preset);
        checkFramePattern(o.output);
        const std::vector<int> frames = range.frames();
        for (size_t i = 0; i < frames.size(); ++i) {
            progress.frameLabel = "frame " + std::to_string(i + 1) + "/" + std::to_string(frames.size()) + " (" +
                                  std::to_string(frames[i]) + "): ";
            meshOne(o, printMm, presetAtFrame(animated, frames[i]), framePath(o.output, frames[i]), context, progress);
        }
        return 0;
    } catch (const mesh::MeshCancelled&) {
        progress.finish();
        std::fprintf(stderr, "fraktal: mesh cancelled; the file under way is not written\n");
        return kCancelledExitCode;
    }
}

}  // namespace

void addMeshCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<MeshOptions>();
    CLI::App* cmd = app.add_subcommand(
        "mesh", "Mesh a preset's fractal for printing: a level set (.vdb) or a closed, manifold mesh");
    cmd->add_option("preset", o->preset, "Preset file (JSON, or a Mandelbulber2 .fract)")->required();
    cmd->add_option("-o,--output", o->output, "Output: .vdb (OpenVDB level set) or .ply, .obj, .stl, .glb (mesh)")
        ->required();
    auto* resolution = cmd->add_option("--resolution", o->resolution,
                                       "Voxels across the bound's diameter, or the --box's largest side (default 256)")
                           ->check(CLI::Range(8, 1 << 20));
    cmd->add_option("--box", o->box,
                    "Mesh only this box, X0,Y0,Z0,X1,Y1,Z1 in the preset's units (a detail, a cut-away), closed "
                    "along its faces")
        ->delimiter(',')
        ->expected(6);
    cmd->add_option("--voxel", o->voxel, "Voxel size in the preset's units (instead of --resolution)")
        ->check(CLI::PositiveNumber)
        ->excludes(resolution);
    auto* frame = cmd->add_option("--frame", o->frame, "Mesh the preset as its animation has it at this frame");
    cmd->add_option("--frames", o->frames,
                    "Mesh an animation's frames A-B[:STEP], one file each: -o names them with a run of # "
                    "(out/mesh_####.ply)")
        ->excludes(frame);
    cmd->add_option("--simplify", o->simplify,
                    "Merge flat regions into larger polygons: OpenVDB's adaptivity, 0 (none) to 1")
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--print-size", o->printSize,
                    "Scale the mesh so that its largest side is this long, in millimetres (100mm, 10cm, 4in)");
    cmd->add_flag("--remove-cavities", o->removeCavities,
                  "Keep only the surface seen from outside: fill the closed cavities inside the fractal (and what "
                  "floats in them), which a print would trap");
    cmd->add_option("--min-thickness", o->minThickness,
                    "Thicken the parts thinner than this (preset units; a nozzle's width at the print size): "
                    "reports the voxels made solid")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--no-color", o->noColor,
                  "Leave out the vertex colours (by default .ply, .obj and .glb carry the preset's palette)");
    cmd->add_option("--device", o->device,
                    "Where the estimate is evaluated: gpu (the renderer's GLSL on OpenGL, single precision), "
                    "cpu (double precision, every core), or auto: the GPU when there is an OpenGL context and "
                    "the voxel is over 1e-5 of the coordinates (else the CPU)")
        ->check(CLI::IsMember({"auto", "cpu", "gpu"}));
    cmd->add_option("--threads", o->threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024));
    cmd->callback([&action, o] { action = [o] { return runMesh(*o); }; });
}

}  // namespace fraktal::cli
