#include "app/editor/document/mesh_export_job.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "core/mesh/brick_sampler.hpp"
#include "core/mesh/mesh_file.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

namespace {

// A number as a person types it ("0.5", not "0.500000").
std::string shortNumber(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", v);
    return text;
}

// The print size typed in millimetres, or 0 when it is not a positive number.
double printSizeMm(const std::string& typed) {
    const char* begin = typed.c_str();
    char* end = nullptr;
    const double mm = std::strtod(begin, &end);
    while (end && std::isspace(static_cast<unsigned char>(*end))) ++end;
    return end != begin && end && *end == '\0' && std::isfinite(mm) && mm > 0.0 ? mm : 0.0;
}

bool blank(const std::string& text) {
    return std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isspace(c); });
}

}  // namespace

std::string meshFormat(const std::string& output) {
    std::string extension = fs::path(output).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    for (const char* format : kMeshFormats)
        if (extension == format) return extension;
    return "";
}

std::string withMeshFormat(const std::string& output, const std::string& format) {
    fs::path path(output);
    if (path.filename().empty()) path /= "fraktal_mesh";
    return path.replace_extension(format).string();
}

std::string meshOptionsError(const MeshExportOptions& o, bool planeDocument) {
    if (planeDocument) return "A 2D document has no surface to mesh.";
    if (fs::path(o.output).filename().empty()) return "Choose a file to write.";
    if (meshFormat(o.output).empty()) {
        std::string list;
        for (const char* format : kMeshFormats) list += (list.empty() ? "" : ", ") + std::string(format);
        return "The file's extension picks the format: one of " + list + ".";
    }
    if (!blank(o.printSizeMm) && meshFormat(o.output) != ".vdb" && printSizeMm(o.printSizeMm) == 0.0)
        return "The print size is a length in millimetres, e.g. 120 (empty: the preset's units).";
    return "";
}

double meshVoxelSize(const Formula& f, int resolution) {
    return mesh::layoutByResolution(f, std::max(resolution, 2)).voxel;
}

bool meshFormatCarriesColours(const std::string& output) { return mesh::carriesColors(meshFormat(output)); }

std::vector<std::string> meshExportCommand(const fs::path& fraktalExe, const fs::path& preset,
                                           const MeshExportOptions& o) {
    // The flags of `fraktal mesh --help` (app/cli/mesh.cpp).
    std::vector<std::string> cmd{fraktalExe.string(),         "mesh", preset.string(), "-o", o.output, "--resolution",
                                 std::to_string(o.resolution)};
    if (o.simplify > 0.0) {
        cmd.push_back("--simplify");
        cmd.push_back(shortNumber(o.simplify));
    }
    // The mesher refuses a print size for a level set: it has no millimetres.
    if (const double mm = printSizeMm(o.printSizeMm); mm > 0.0 && meshFormat(o.output) != ".vdb") {
        cmd.push_back("--print-size");
        cmd.push_back(shortNumber(mm) + "mm");
    }
    if (o.removeCavities) cmd.push_back("--remove-cavities");
    if (o.minThickness > 0.0) {
        cmd.push_back("--min-thickness");
        cmd.push_back(shortNumber(o.minThickness));
    }
    if (!o.vertexColours && meshFormatCarriesColours(o.output)) cmd.push_back("--no-color");
    return cmd;
}

bool startMeshExport(MeshExportJob& job, const std::string& presetText, double now) {
    job.program = "the mesher";
    job.outputs = {job.options.output};
    job.resolution = job.options.resolution;
    if (const std::string error = meshOptionsError(job.options); !error.empty()) {
        job.log = error;
        job.status = ExportStatus::Failed;
        return false;
    }
    job.presetFile = exportPresetFile(job.options.output, ".mesh.json");
    return startExportProcess(job, presetText, meshExportCommand(exportExecutable(job), job.presetFile, job.options),
                              now);
}

namespace {

// The last line of `log` that starts with `prefix`, without it ("" when none).
std::string lastLineAfter(const std::string& log, const std::string& prefix) {
    size_t at = log.rfind("\n" + prefix);
    if (at != std::string::npos)
        ++at;
    else if (log.starts_with(prefix))
        at = 0;
    else
        return "";
    const size_t begin = at + prefix.size();
    const size_t end = log.find_first_of("\r\n", begin);
    return log.substr(begin, end == std::string::npos ? std::string::npos : end - begin);
}

}  // namespace

std::string meshProgressStage(const std::string& log) {
    const std::string line = lastLineAfter(log, "progress: ");
    const size_t percent = line.rfind(" (");
    return percent == std::string::npos ? line : line.substr(0, percent);
}

std::string meshExportStatusText(const MeshExportJob& job) {
    switch (job.status) {
        case ExportStatus::Running: return "";
        case ExportStatus::Cancelling: return "Cancelling after the current batch...";
        case ExportStatus::Cancelled: return "Cancelled: no file written.";
        case ExportStatus::Idle: return "The editor stays usable while it meshes; Cancel leaves no file.";
        case ExportStatus::Done: {
            if (!exportOutputsExist(job)) return "The file of the last export is no longer there.";
            // The mesher's summary: "wrote out.ply: 81920 triangles, 40962 vertices, volume ...".
            const std::string summary = lastLineAfter(job.log, "wrote ");
            return "Done: " + (summary.empty() ? job.outputs[0].string() : summary);
        }
        case ExportStatus::Failed: return exportFailureText(job);
    }
    return "";
}

}  // namespace fraktal::editor
