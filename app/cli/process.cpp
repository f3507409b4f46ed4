#include "cli/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>

extern char** environ;

namespace fraktal::cli {

namespace {

void readAll(int fd, std::string* into) {
    std::array<char, 65536> buf;
    for (;;) {
        const ssize_t n = ::read(fd, buf.data(), buf.size());
        if (n > 0) {
            into->append(buf.data(), size_t(n));
        } else if (n < 0 && errno == EINTR) {
            continue;
        } else {
            break;
        }
    }
    ::close(fd);
}

}  // namespace

std::string ProgramResult::describeStatus() const {
    return signal ? "killed by signal " + std::to_string(signal) : "exit status " + std::to_string(exitCode);
}

RunningProgram::RunningProgram(const std::vector<std::string>& argv) {
    if (argv.empty()) throw ProgramNotStarted("no program given");
    int in[2], out[2], err[2];
    if (::pipe2(in, O_CLOEXEC) != 0) throw ProgramNotStarted(std::string("pipe: ") + std::strerror(errno));
    if (::pipe2(out, O_CLOEXEC) != 0) {
        ::close(in[0]), ::close(in[1]);
        throw ProgramNotStarted(std::string("pipe: ") + std::strerror(errno));
    }
    if (::pipe2(err, O_CLOEXEC) != 0) {
        ::close(in[0]), ::close(in[1]), ::close(out[0]), ::close(out[1]);
        throw ProgramNotStarted(std::string("pipe: ") + std::strerror(errno));
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_adddup2(&actions, in[0], STDIN_FILENO);
    posix_spawn_file_actions_adddup2(&actions, out[1], STDOUT_FILENO);
    posix_spawn_file_actions_adddup2(&actions, err[1], STDERR_FILENO);
    // We ignore SIGPIPE (a program that stops reading is an error we report, not a crash); the
    // child gets the default back.
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t defaults;
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGPIPE);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETSIGDEF);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int rc = posix_spawnp(&pid_, args[0], &actions, &attr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    ::close(in[0]), ::close(out[1]), ::close(err[1]);
    if (rc != 0) {
        ::close(in[1]), ::close(out[0]), ::close(err[0]);
        pid_ = -1;
        throw ProgramNotStarted("cannot run " + argv[0] + ": " + std::strerror(rc) +
                                (rc == ENOENT ? " (not found on PATH)" : ""));
    }
    std::signal(SIGPIPE, SIG_IGN);
    stdinFd_ = in[1];
    outReader_ = std::thread(readAll, out[0], &out_);
    errReader_ = std::thread(readAll, err[0], &err_);
}

bool RunningProgram::write(std::span<const uint8_t> bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(stdinFd_, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes = bytes.subspan(size_t(n));
    }
    return true;
}

ProgramResult RunningProgram::wait() {
    ProgramResult r;
    if (stdinFd_ >= 0) ::close(stdinFd_);
    stdinFd_ = -1;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
    waited_ = true;
    outReader_.join();
    errReader_.join();
    if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
    if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
    r.out = std::move(out_);
    r.err = std::move(err_);
    return r;
}

RunningProgram::~RunningProgram() {
    if (waited_ || pid_ < 0) return;
    ::kill(pid_, SIGKILL);
    wait();
}

ProgramResult runProgram(const std::vector<std::string>& argv) { return RunningProgram(argv).wait(); }

std::string tailOf(const std::string& text, size_t maxChars) {
    size_t end = text.find_last_not_of(" \n\r\t");
    if (end == std::string::npos) return "";
    ++end;
    const size_t begin = end > maxChars ? end - maxChars : 0;
    return (begin > 0 ? "..." : "") + text.substr(begin, end - begin);
}

}  // namespace fraktal::cli
