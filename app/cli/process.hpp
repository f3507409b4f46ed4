// Running another program (ffmpeg, sbatch, squeue) from an argument vector: posix_spawnp, never a
// shell command line, so no file name or option is ever interpreted by a shell.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace fraktal::cli {

struct ProgramResult {
    int exitCode = -1;  // -1 when the program was ended by a signal
    int signal = 0;
    std::string out, err;
    // "exit status N" or "killed by signal N".
    std::string describeStatus() const;
};

// Thrown when the program cannot be started (not on PATH, not executable).
struct ProgramNotStarted : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A running program: we write its standard input; its standard output and error are collected
// (by threads, so that a chatty program never blocks on a full pipe while we write).
class RunningProgram {
   public:
    // argv[0] is looked up on PATH. Throws ProgramNotStarted naming it and the reason.
    explicit RunningProgram(const std::vector<std::string>& argv);
    ~RunningProgram();  // a program not waited for is killed and reaped
    RunningProgram(const RunningProgram&) = delete;
    RunningProgram& operator=(const RunningProgram&) = delete;

    // False when the program no longer reads its input (it exited or closed it).
    bool write(std::span<const uint8_t> bytes);
    // Closes its input and waits for it to exit.
    ProgramResult wait();

   private:
    pid_t pid_ = -1;
    int stdinFd_ = -1;
    std::string out_, err_;
    std::thread outReader_, errReader_;
    bool waited_ = false;
};

// Runs argv with empty input and returns its status and output.
ProgramResult runProgram(const std::vector<std::string>& argv);

// The last `maxChars` characters of a program's error output, trimmed, for an error message.
std::string tailOf(const std::string& text, size_t maxChars = 2000);

}  // namespace fraktal::cli
