#include "app/editor/document/export_job.hpp"

#include <algorithm>

namespace fraktal::editor {

namespace fs = std::filesystem;

std::vector<std::string> exportCommand(const fs::path& fraktalExe, const fs::path& preset, const ExportOptions& o) {
    // The flags of `fraktal render --help` (app/cli/render.cpp). Exposure, OCIO display/view and
    // working space travel in the preset's render section.
    std::vector<std::string> cmd{fraktalExe.string(),
                                 "render",
                                 preset.string(),
                                 "-o",
                                 o.output + ".exr",
                                 "--size",
                                 std::to_string(o.width) + "x" + std::to_string(o.height),
                                 "--spp",
                                 std::to_string(exportSpp(o))};
    if (o.pathTraced) {
        cmd.push_back("--mode");
        cmd.push_back("path");
        if (o.denoise) cmd.push_back("--denoise");
    }
    if (o.pngPreview) {
        cmd.push_back("--png");
        cmd.push_back(o.output + ".png");
    }
    if (!o.halfFloat) cmd.push_back("--float");
    return cmd;
}

void followViewMode(ExportOptions& o, bool pathTraceAtRest, int pathSppCap) {
    if (o.followed && o.followedPathTraced == pathTraceAtRest && o.followedPathSpp == pathSppCap) return;
    o.followed = true;
    o.followedPathTraced = o.pathTraced = pathTraceAtRest;
    o.followedPathSpp = o.pathSpp = pathSppCap;
}

int exportSpp(const ExportOptions& o) { return o.pathTraced ? o.pathSpp : o.spp; }

std::string exportLightsText(const Lighting& lighting, bool pathTraced) {
    // Enabled lights by type, in the Lights tab's words: "2 sphere lights, 1 rect light".
    std::vector<std::string> parts;
    for (const LightTypeNames& t : kLightTypeNames) {
        const auto n = std::count_if(lighting.lights.begin(), lighting.lights.end(),
                                     [&](const Light& l) { return l.enabled && l.type == t.type; });
        if (n == 0) continue;
        std::string label = t.label;
        std::transform(label.begin(), label.end(), label.begin(), ::tolower);
        parts.push_back(std::to_string(n) + " " + label + (n == 1 ? " light" : " lights"));
    }
    if (lighting.environment.active()) parts.push_back("the environment map");
    std::string list;
    for (size_t i = 0; i < parts.size(); ++i) list += (i == 0 ? "" : i + 1 == parts.size() ? " and " : ", ") + parts[i];
    if (pathTraced)
        return list.empty() ? "Lights: the preset has none of its own (the Lights tab adds them)."
                            : "Lights: the preset's " + list + " (the Lights tab).";
    return list.empty() ? ""
                        : "The fast renderer leaves out the preset's " + list + ": choose Path traced to render them.";
}

std::string exportPresetText(const Document& d, const fs::path& documentFile) {
    const std::string& map = d.preset.lighting.environment.map;
    if (d.plane || map.empty() || fs::path(map).is_absolute() || documentFile.empty()) return documentFileText(d);
    Document copy = d;
    copy.preset.lighting.environment.map = (fs::absolute(documentFile).parent_path() / map).lexically_normal().string();
    return documentFileText(copy);
}

bool startExport(ExportJob& job, const Preset& preset, double now) {
    return startExport(job, presetToJson(preset).dump(2), now);
}

bool startExport(ExportJob& job, const std::string& presetText, double now) {
    job.outputs = {job.options.output + ".exr"};
    if (job.options.pngPreview) job.outputs.push_back(job.options.output + ".png");
    job.pathTraced = job.options.pathTraced;
    job.spp = exportSpp(job.options);
    job.program = "the renderer";
    job.presetFile = exportPresetFile(job.options.output, ".export.json");
    return startExportProcess(job, presetText, exportCommand(exportExecutable(job), job.presetFile, job.options), now);
}

std::string exportStatusText(const ExportJob& job) {
    switch (job.status) {
        case ExportStatus::Running: return "";
        case ExportStatus::Cancelling: return "Cancelling after the current tile...";
        case ExportStatus::Cancelled: return "Cancelled.";
        case ExportStatus::Idle: return "The UI stays usable while it renders.";
        case ExportStatus::Done: {
            if (!exportOutputsExist(job)) return "The files of the last export are no longer there.";
            std::string text = "Done: " + job.outputs[0].string();
            for (size_t i = 1; i < job.outputs.size(); ++i) text += " and " + job.outputs[i].string();
            return text + (job.pathTraced ? " (path traced, " : " (fast, ") + std::to_string(job.spp) + " spp).";
        }
        case ExportStatus::Failed: return exportFailureText(job);
    }
    return "";
}

}  // namespace fraktal::editor
