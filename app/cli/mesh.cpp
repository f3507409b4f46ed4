// `fraktal mesh PRESET -o OUT.{vdb,ply,obj,stl,glb}`: the preset's fractal as a sparse
// narrow-band level set (OpenVDB) and a closed, manifold triangle mesh for printing
// (core/mesh/mesh_formula.hpp).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <regex>

#include "cli/commands.hpp"
#include "core/atomic_file.hpp"
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
    std::optional<int> frame;
    double simplify = 0.0;
    std::string printSize;
    int threads = 0;
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

Preset meshedPreset(const MeshOptions& o) {
    if (isPlanePresetFile(o.preset))
        throw std::runtime_error(o.preset + ": a 2D preset has no surface to mesh (mesh a 3D preset)");
    return sceneAtFrame(o.preset, o.frame);
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

int runMesh(const MeshOptions& o) {
    const std::filesystem::path output(o.output);
    const std::string extension = output.extension().string();
    const bool vdb = extension == ".vdb";
    if (!vdb && !mesh::isMeshExtension(extension))
        throw std::runtime_error(o.output + ": unknown output format \"" + extension + "\" (one of .vdb, " +
                                 mesh::meshExtensions() + ")");
    std::optional<double> printMm;
    if (!o.printSize.empty()) {
        if (vdb)
            throw std::runtime_error(o.output +
                                     ": --print-size scales a mesh; a .vdb keeps the preset's units (its voxel size)");
        printMm = parsePrintSize(o.printSize);
    }
    // The output's folder is checked before any work (AtomicFile creates nothing yet).
    { AtomicFile check(output); }
    const Preset preset = meshedPreset(o);
    const Formula& f = preset.formula;
    if (!f.cpuEvaluable())
        throw std::runtime_error(o.preset +
                                 ": custom GLSL blocks cannot be meshed yet (the mesher evaluates on the CPU)");

    mesh::MeshSettings settings;
    settings.layout = o.voxel ? mesh::layoutByVoxel(f, *o.voxel) : mesh::layoutByResolution(f, o.resolution);
    settings.adaptivity = o.simplify;
    settings.threads = o.threads;
    const auto start = std::chrono::steady_clock::now();
    const mesh::BrickPlan plan = mesh::planBricks(f, settings.layout, settings.memoryLimitBytes, settings.threads);
    const int across = settings.layout.voxelsAcross;
    std::printf("%s: %d^3 voxels of %g, %zu of %lld bricks near the surface (%.1fs)\n", o.preset.c_str(), across,
                settings.layout.voxel, plan.bricks.size(),
                (long long)std::pow(double(settings.layout.bricksAcross()), 3.0), secondsSince(start));
    std::fflush(stdout);
    const mesh::SdfVolume volume = mesh::SdfVolume::build(f, plan, settings.threads);
    std::printf("level set: %lld active voxels, %.1f MiB (%.1fs)\n", (long long)volume.activeVoxels(),
                double(volume.memoryBytes()) / (1024.0 * 1024.0), secondsSince(start));
    if (vdb) {
        volume.writeVdb(output);
        std::printf("wrote %s (%.1fs)\n", o.output.c_str(), secondsSince(start));
        return 0;
    }
    mesh::TriangleMesh m = volume.toMesh(o.simplify);
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
    std::printf("wrote %s: %zu triangles, %zu vertices, volume %.6g, %.4g x %.4g x %.4g%s (%.1fs)\n", o.output.c_str(),
                m.triangles.size(), m.points.size(), m.enclosedVolume(), extent.x, extent.y, extent.z,
                printMm ? " mm" : "", secondsSince(start));
    return 0;
}

}  // namespace

void addMeshCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<MeshOptions>();
    CLI::App* cmd = app.add_subcommand(
        "mesh", "Mesh a preset's fractal for printing: a level set (.vdb) or a closed, manifold mesh");
    cmd->add_option("preset", o->preset, "Preset file (JSON, or a Mandelbulber2 .fract)")->required();
    cmd->add_option("-o,--output", o->output, "Output: .vdb (OpenVDB level set) or .ply, .obj, .stl, .glb (mesh)")
        ->required();
    auto* resolution =
        cmd->add_option("--resolution", o->resolution, "Voxels across the bound's diameter (default 256)")
            ->check(CLI::Range(8, 1 << 20));
    cmd->add_option("--voxel", o->voxel, "Voxel size in the preset's units (instead of --resolution)")
        ->check(CLI::PositiveNumber)
        ->excludes(resolution);
    cmd->add_option("--frame", o->frame, "Mesh the preset as its animation has it at this frame");
    cmd->add_option("--simplify", o->simplify,
                    "Merge flat regions into larger polygons: OpenVDB's adaptivity, 0 (none) to 1")
        ->check(CLI::Range(0.0, 1.0));
    cmd->add_option("--print-size", o->printSize,
                    "Scale the mesh so that its largest side is this long, in millimetres (100mm, 10cm, 4in)");
    cmd->add_option("--threads", o->threads, "Threads (default: all cores)")->check(CLI::Range(1, 1024));
    cmd->callback([&action, o] { action = [o] { return runMesh(*o); }; });
}

}  // namespace fraktal::cli
