// Under the sanitizers, the fraktal command lines that the tests start (test::runCli, fork and
// exec, Slurm jobs) run without LeakSanitizer; the test binary itself keeps it.
//
// LeakSanitizer's thread tracer crashes now and then in a short-lived child ("Tracer caught
// signal 11", then "LeakSanitizer has encountered a fatal error" and exit code 1:
// google/sanitizers#1353). It has failed CI in a different test each time (a re-render from an
// EXR; the frames of the encoding test, also with the leak check at the end of main, so it is
// not exit's teardown of threads), and the frame-repair test on every run on one machine; 200
// runs of the same commands on another did not crash it. A test cannot tell that exit code from
// the command's own. The command line's own paths are leak-checked by scripts/cli_leak_check.sh,
// which runs each command in a process of its own and tells the tracer's crash from a leak.
#include <cstdlib>
#include <string>

namespace {

#if defined(__SANITIZE_ADDRESS__)
// Before main: the children inherit the environment; this process parsed its options already.
const bool childrenWithoutLeakCheck = [] {
    const char* options = std::getenv("ASAN_OPTIONS");
    const std::string withLeaksOff =
        std::string(options ? options : "") + (options && *options ? ":" : "") + "detect_leaks=0";
    return ::setenv("ASAN_OPTIONS", withLeaksOff.c_str(), 1) == 0;
}();
#endif

}  // namespace
