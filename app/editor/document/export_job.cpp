#include "app/editor/document/export_job.hpp"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <regex>

#include "core/atomic_file.hpp"

extern char** environ;

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

double parseProgress(const std::string& log) {
    const std::regex percent(R"((\d{1,3}(?:\.\d+)?)\s*%)");
    double last = -1.0;
    for (std::sregex_iterator it(log.begin(), log.end(), percent), end; it != end; ++it)
        last = std::clamp(std::stod((*it)[1]) / 100.0, 0.0, 1.0);
    return last;
}

bool startExport(ExportJob& job, const Preset& preset, double now) {
    return startExport(job, presetToJson(preset).dump(2), now);
}

bool startExport(ExportJob& job, const std::string& presetText, double now) {
    job.log.clear();
    job.progress = -1.0;
    job.startedAt = now;
    job.outputs = {job.options.output + ".exr"};
    if (job.options.pngPreview) job.outputs.push_back(job.options.output + ".png");
    job.pathTraced = job.options.pathTraced;
    job.spp = exportSpp(job.options);
    const fs::path out(job.options.output);
    job.presetFile =
        (out.has_parent_path() ? out.parent_path() : fs::path(".")) / ("." + out.filename().string() + ".export.json");
    try {
        writeFileAtomically(job.presetFile, presetText, /*keepBackup=*/false);
    } catch (const std::exception& e) {
        job.log = e.what();
        job.status = ExportStatus::Failed;
        return false;
    }
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0) {
        job.log = std::string("cannot start the renderer: ") + std::strerror(errno);
        job.status = ExportStatus::Failed;
        return false;
    }
    const fs::path exe = job.executable.empty() ? fs::read_symlink("/proc/self/exe") : job.executable;
    const std::vector<std::string> args = exportCommand(exe, job.presetFile, job.options);
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, pipeFds[1], STDERR_FILENO);
    const int rc = posix_spawn(&job.pid, argv[0], &actions, nullptr, argv.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    ::close(pipeFds[1]);
    if (rc != 0) {
        ::close(pipeFds[0]);
        job.log = std::string("cannot start the renderer: ") + std::strerror(rc);
        job.status = ExportStatus::Failed;
        return false;
    }
    ::fcntl(pipeFds[0], F_SETFL, O_NONBLOCK);
    job.outputFd = pipeFds[0];
    job.status = ExportStatus::Running;
    return true;
}

bool exportActive(const ExportJob& job) {
    return job.status == ExportStatus::Running || job.status == ExportStatus::Cancelling;
}

void exportOptionsEdited(ExportJob& job) {
    if (!exportActive(job)) job.status = ExportStatus::Idle;
}

bool exportOutputsExist(const ExportJob& job) {
    std::error_code ec;
    return !job.outputs.empty() && std::all_of(job.outputs.begin(), job.outputs.end(),
                                               [&](const fs::path& f) { return fs::is_regular_file(f, ec); });
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
        case ExportStatus::Failed: {
            // The log's last line says why (the renderer's error, or why it could not start).
            std::string last;
            if (const size_t end = job.log.find_last_not_of("\r\n "); end != std::string::npos) {
                const size_t newline = job.log.find_last_of('\n', end);
                const size_t begin = newline == std::string::npos ? 0 : newline + 1;
                last = job.log.substr(begin, end + 1 - begin);
            }
            if (last.size() > 240) last = last.substr(0, 240) + "...";
            return last.empty() ? "Failed (see log)." : "Failed: " + last;
        }
    }
    return "";
}

namespace {

// The child is gone: close the pipe, remove the temporary preset, settle the status.
void reap(ExportJob& job, int wstatus) {
    ::close(job.outputFd);
    job.outputFd = -1;
    job.pid = -1;
    std::error_code ec;
    fs::remove(job.presetFile, ec);
    if (job.status == ExportStatus::Cancelling) {
        job.status = ExportStatus::Cancelled;
        return;
    }
    job.status = WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 ? ExportStatus::Done : ExportStatus::Failed;
    // Done only for files that are there: a renderer that exits 0 without writing one failed.
    for (const fs::path& f : job.outputs)
        if (job.status == ExportStatus::Done && !fs::is_regular_file(f, ec)) {
            job.log += (job.log.empty() || job.log.back() == '\n' ? "" : "\n") +
                       std::string("the renderer exited without writing ") + f.string() + "\n";
            job.status = ExportStatus::Failed;
        }
}

void drain(ExportJob& job) {
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(job.outputFd, buffer, sizeof buffer);
        if (n <= 0) break;
        job.log.append(buffer, size_t(n));
    }
    if (job.log.size() > (1u << 20)) job.log.erase(0, job.log.size() - (1u << 19));
}

}  // namespace

void pollExport(ExportJob& job) {
    if (!exportActive(job)) return;
    drain(job);
    job.progress = parseProgress(job.log);
    int wstatus = 0;
    if (::waitpid(job.pid, &wstatus, WNOHANG) != job.pid) return;
    drain(job);
    reap(job, wstatus);
}

void cancelExport(ExportJob& job) {
    if (job.status != ExportStatus::Running || job.pid <= 0) return;
    // The renderer stops between tiles on SIGTERM and writes nothing (app/cli/render.cpp).
    ::kill(job.pid, SIGTERM);
    job.status = ExportStatus::Cancelling;
}

void finishExport(ExportJob& job) {
    if (!exportActive(job)) return;
    cancelExport(job);
    int wstatus = 0;
    ::waitpid(job.pid, &wstatus, 0);
    drain(job);
    reap(job, wstatus);
}

}  // namespace fraktal::editor
