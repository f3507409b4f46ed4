// What the still export (export_job.hpp) and the mesh export (mesh_export_job.hpp) share: the
// document written to a temporary preset, a `fraktal` command run on it in a child process (so
// the editor stays responsive, a cancel is a signal, and a crash in a huge job cannot take the
// unsaved document with it), its output read without blocking, progress taken from its "NN%"
// (`fraktal render` and `fraktal mesh` print "progress: ... (NN%)" lines when their stderr is not
// a terminal), and Done only for a child that exited 0 having written every file it was asked for.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>
#include <vector>

namespace fraktal::editor {

// Cancelling: the child got SIGTERM and stops at its next tile or batch (it writes nothing).
enum class ExportStatus { Idle, Running, Cancelling, Done, Failed, Cancelled };
// "idle", "running", ..., as the state file writes it.
const char* exportStatusName(ExportStatus status);

struct ExportProcess {
    ExportStatus status = ExportStatus::Idle;
    pid_t pid = -1;
    int outputFd = -1;
    std::string log;         // the child's output so far
    double progress = -1.0;  // 0..1, or < 0 when the child has not said
    double startedAt = 0.0;
    std::filesystem::path presetFile;  // the temp preset handed to the child
    std::filesystem::path executable;  // the fraktal binary to run; empty: this program
    // The files this job was asked to write, kept from its start: the options may change after it;
    // Done means the child exited with 0 and all of them exist.
    std::vector<std::filesystem::path> outputs;
    std::string program = "the renderer";  // the child, in the messages ("the mesher")
};

// The fraktal binary the job runs: its `executable`, or this program.
std::filesystem::path exportExecutable(const ExportProcess& job);
// The temporary preset for an output: hidden beside it, ".NAME.SUFFIX" (the child reads it from
// there, so that a relative path in the preset resolves as it does for the output).
std::filesystem::path exportPresetFile(const std::filesystem::path& output, const std::string& suffix);

// Writes `presetText` to job.presetFile and starts `args` (args[0]: the program); false with
// job.log saying why. job.outputs and job.presetFile are set by the caller first.
bool startExportProcess(ExportProcess& job, const std::string& presetText, const std::vector<std::string>& args,
                        double now);
// Reads the child's output without blocking and notices when it ended.
void pollExport(ExportProcess& job);
// Asks the child to stop (SIGTERM) and returns at once; pollExport sees it end.
void cancelExport(ExportProcess& job);
// Cancels and waits for the child to exit (when the editor quits).
void finishExport(ExportProcess& job);
bool exportActive(const ExportProcess& job);  // Running or Cancelling
// The options changed after a job ended: its Done, Failed or Cancelled no longer describes them.
void exportOptionsEdited(ExportProcess& job);
// Whether every file the job wrote is there now.
bool exportOutputsExist(const ExportProcess& job);
// "Failed: " and the log's last line (the child's error, or why it could not start).
std::string exportFailureText(const ExportProcess& job);
// The last "NN%" or "NN.N%" in `log` as 0..1, or -1.
double parseProgress(const std::string& log);
// A command's words joined by spaces, as the dialogs and the state file show it.
std::string commandLine(const std::vector<std::string>& args);

}  // namespace fraktal::editor
