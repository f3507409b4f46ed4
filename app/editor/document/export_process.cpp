#include "app/editor/document/export_process.hpp"

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

const char* exportStatusName(ExportStatus status) {
    static constexpr const char* kNames[] = {"idle", "running", "cancelling", "done", "failed", "cancelled"};
    return kNames[int(status)];
}

fs::path exportExecutable(const ExportProcess& job) {
    return job.executable.empty() ? fs::read_symlink("/proc/self/exe") : job.executable;
}

fs::path exportPresetFile(const fs::path& output, const std::string& suffix) {
    return (output.has_parent_path() ? output.parent_path() : fs::path(".")) /
           ("." + output.filename().string() + suffix);
}

double parseProgress(const std::string& log) {
    const std::regex percent(R"((\d{1,3}(?:\.\d+)?)\s*%)");
    double last = -1.0;
    for (std::sregex_iterator it(log.begin(), log.end(), percent), end; it != end; ++it)
        last = std::clamp(std::stod((*it)[1]) / 100.0, 0.0, 1.0);
    return last;
}

std::string commandLine(const std::vector<std::string>& args) {
    std::string line;
    for (const std::string& a : args) line += (line.empty() ? "" : " ") + a;
    return line;
}

namespace {

bool failToStart(ExportProcess& job, const std::string& why) {
    job.log = why;
    job.status = ExportStatus::Failed;
    return false;
}

}  // namespace

bool startExportProcess(ExportProcess& job, const std::string& presetText, const std::vector<std::string>& args,
                        double now) {
    job.log.clear();
    job.progress = -1.0;
    job.startedAt = now;
    try {
        writeFileAtomically(job.presetFile, presetText, /*keepBackup=*/false);
    } catch (const std::exception& e) {
        return failToStart(job, e.what());
    }
    int pipeFds[2];
    if (::pipe2(pipeFds, O_CLOEXEC) != 0) {
        std::error_code ec;
        fs::remove(job.presetFile, ec);
        return failToStart(job, "cannot start " + job.program + ": " + std::strerror(errno));
    }
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
        job.pid = -1;
        std::error_code ec;
        fs::remove(job.presetFile, ec);
        return failToStart(job, "cannot start " + job.program + ": " + std::strerror(rc));
    }
    ::fcntl(pipeFds[0], F_SETFL, O_NONBLOCK);
    job.outputFd = pipeFds[0];
    job.status = ExportStatus::Running;
    return true;
}

bool exportActive(const ExportProcess& job) {
    return job.status == ExportStatus::Running || job.status == ExportStatus::Cancelling;
}

void exportOptionsEdited(ExportProcess& job) {
    if (!exportActive(job)) job.status = ExportStatus::Idle;
}

bool exportOutputsExist(const ExportProcess& job) {
    std::error_code ec;
    return !job.outputs.empty() && std::all_of(job.outputs.begin(), job.outputs.end(),
                                               [&](const fs::path& f) { return fs::is_regular_file(f, ec); });
}

std::string exportFailureText(const ExportProcess& job) {
    std::string last;
    if (const size_t end = job.log.find_last_not_of("\r\n "); end != std::string::npos) {
        const size_t newline = job.log.find_last_of('\n', end);
        const size_t begin = newline == std::string::npos ? 0 : newline + 1;
        last = job.log.substr(begin, end + 1 - begin);
    }
    if (last.size() > 240) last = last.substr(0, 240) + "...";
    return last.empty() ? "Failed (see log)." : "Failed: " + last;
}

namespace {

// A child killed before it could clean up (a signal it does not catch) leaves its AtomicFile's
// temporary, "<folder>/.<name>.tmp-<pid>-<n><extension>" (core/atomic_file.hpp), beside an output.
void removeChildTemporaries(const ExportProcess& job, pid_t pid) {
    std::error_code ec;
    for (const fs::path& out : job.outputs) {
        const fs::path folder = out.has_parent_path() ? out.parent_path() : fs::path(".");
        const std::string prefix = "." + out.filename().string() + ".tmp-" + std::to_string(pid) + "-";
        for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
            if (it->path().filename().string().starts_with(prefix)) fs::remove(it->path(), ec);
    }
}

// The child is gone: close the pipe, remove the temporary preset, settle the status.
void reap(ExportProcess& job, int wstatus) {
    const pid_t pid = job.pid;
    ::close(job.outputFd);
    job.outputFd = -1;
    job.pid = -1;
    std::error_code ec;
    fs::remove(job.presetFile, ec);
    const bool exitedZero = WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0;
    // A child that finished before the signal reached it wrote its files: they are there, so the
    // job is Done, not Cancelled beside a file the dialog would not mention.
    if (job.status == ExportStatus::Cancelling && !(exitedZero && exportOutputsExist(job))) {
        job.status = ExportStatus::Cancelled;
        removeChildTemporaries(job, pid);
        return;
    }
    job.status = exitedZero ? ExportStatus::Done : ExportStatus::Failed;
    // Done only for files that are there: a child that exits 0 without writing one failed.
    for (const fs::path& f : job.outputs)
        if (job.status == ExportStatus::Done && !fs::is_regular_file(f, ec)) {
            job.log += (job.log.empty() || job.log.back() == '\n' ? "" : "\n") + job.program +
                       " exited without writing " + f.string() + "\n";
            job.status = ExportStatus::Failed;
        }
    if (job.status == ExportStatus::Failed) removeChildTemporaries(job, pid);
}

void drain(ExportProcess& job) {
    char buffer[4096];
    for (;;) {
        const ssize_t n = ::read(job.outputFd, buffer, sizeof buffer);
        if (n <= 0) break;
        job.log.append(buffer, size_t(n));
    }
    if (job.log.size() > (1u << 20)) job.log.erase(0, job.log.size() - (1u << 19));
}

}  // namespace

void pollExport(ExportProcess& job) {
    if (!exportActive(job)) return;
    drain(job);
    job.progress = parseProgress(job.log);
    int wstatus = 0;
    if (::waitpid(job.pid, &wstatus, WNOHANG) != job.pid) return;
    drain(job);
    job.progress = parseProgress(job.log);
    reap(job, wstatus);
}

void cancelExport(ExportProcess& job) {
    if (job.status != ExportStatus::Running || job.pid <= 0) return;
    // `fraktal render` stops between tiles on SIGTERM and `fraktal mesh` between batches; neither
    // writes anything then (app/cli/cancel.hpp).
    ::kill(job.pid, SIGTERM);
    job.status = ExportStatus::Cancelling;
}

void finishExport(ExportProcess& job) {
    if (!exportActive(job)) return;
    cancelExport(job);
    int wstatus = 0;
    ::waitpid(job.pid, &wstatus, 0);
    drain(job);
    reap(job, wstatus);
}

}  // namespace fraktal::editor
