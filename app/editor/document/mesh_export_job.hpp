// The mesh export dialog's job (File > Export mesh...): the document's fractal meshed for printing
// by `fraktal mesh` (app/cli/mesh.cpp, core/mesh) in a child process (export_process.hpp: the
// child, its progress, cancel and the Done rule, shared with the still export).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "app/editor/document/export_process.hpp"
#include "core/formula.hpp"

namespace fraktal::editor {

// The formats `fraktal mesh` writes, chosen by the output's extension: the meshes, then the
// OpenVDB level set.
inline constexpr const char* kMeshFormats[] = {".ply", ".glb", ".obj", ".stl", ".vdb"};

struct MeshExportOptions {
    std::string output = "fraktal_mesh.ply";  // the path; its extension picks the format
    int resolution = 256;                     // voxels across the bound (`--resolution`, its default)
    double simplify = 0.0;                    // `--simplify`: 0 (every voxel's facet) to 1
    // The largest side's length in millimetres (`--print-size`), as typed; empty: the preset's
    // units. A mesh only: a .vdb keeps the preset's units, its voxel size.
    std::string printSizeMm;
    bool removeCavities = false;  // `--remove-cavities`: fill the closed cavities a print would trap
    double minThickness = 0.0;    // `--min-thickness`, in the preset's units: thicken thinner parts; 0: off
    // The preset's palette as vertex colours (else `--no-color`), for the formats that carry them.
    bool vertexColours = true;
};

struct MeshExportJob : ExportProcess {
    MeshExportOptions options;
    int resolution = 0;  // the resolution this job meshes at
};

// The output's format: its extension in lower case if `fraktal mesh` writes it, else "".
std::string meshFormat(const std::string& output);
// The output with its extension replaced by `format` (".glb"), or added when it has none.
std::string withMeshFormat(const std::string& output, const std::string& format);
// Why the options cannot be meshed ("" when they can): a 2D document (`planeDocument`: a plane has
// no surface), an unknown format, a print size that is not a positive number of millimetres.
std::string meshOptionsError(const MeshExportOptions& o, bool planeDocument = false);
// The voxel size the resolution gives the formula, in the preset's units.
double meshVoxelSize(const Formula& f, int resolution);
// Whether the output's format carries vertex colours (.ply, .obj, .glb).
bool meshFormatCarriesColours(const std::string& output);

// The command line for the mesher (`fraktal mesh`), for the dialog to show and the job to run.
std::vector<std::string> meshExportCommand(const std::filesystem::path& fraktalExe, const std::filesystem::path& preset,
                                           const MeshExportOptions& o);

// Writes the preset's file text beside the output and starts the mesher; false with job.log
// saying why (and nothing started) for options that cannot be meshed.
bool startMeshExport(MeshExportJob& job, const std::string& presetText, double now);
// The stage of the mesher's last progress line ("sampling bricks" of
// "progress: sampling bricks (40%)"), or "".
std::string meshProgressStage(const std::string& log);
// The dialog's line for the job's state: "Done: out/sponge.ply, 81920 triangles ..." (the file it
// wrote, while it exists, with the mesher's summary), "Failed: ..." (the mesher's error); "" while
// it runs (a progress bar).
std::string meshExportStatusText(const MeshExportJob& job);

}  // namespace fraktal::editor
