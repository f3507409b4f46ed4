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
                                 std::to_string(o.spp)};
    if (o.pngPreview) {
        cmd.push_back("--png");
        cmd.push_back(o.output + ".png");
    }
    if (!o.halfFloat) cmd.push_back("--float");
    return cmd;
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

namespace {

// The child is gone: close the pipe, remove the temporary preset, settle the status.
void reap(ExportJob& job, int wstatus) {
    ::close(job.outputFd);
    job.outputFd = -1;
    job.pid = -1;
    std::error_code ec;
    fs::remove(job.presetFile, ec);
    if (job.status == ExportStatus::Cancelling)
        job.status = ExportStatus::Cancelled;
    else
        job.status = WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0 ? ExportStatus::Done : ExportStatus::Failed;
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
