// Under the sanitizers, the fraktal command lines that the tests start (test::runCli, fork and
// exec, Slurm jobs) run without LeakSanitizer; the test binary itself keeps it.
//
// LeakSanitizer's thread tracer crashes now and then in a short-lived child ("Tracer caught
// signal 11", then "LeakSanitizer has encountered a fatal error" and exit code 1:
// google/sanitizers#1353). It has failed CI in a different test each time (a re-render from an
// EXR; the frames of the encoding test; the path-traced frame sequence), and the frame-repair
// test on every run on one machine; 200 runs of the same commands on another did not crash it.
// A test cannot tell that exit code from the command's own. The command line's own paths are
// leak-checked by scripts/cli_leak_check.sh, which runs each command in a process of its own and
// tells the tracer's crash from a leak.
//
// Whether AddressSanitizer is in the process is asked of the process itself (its runtime's entry
// point, a weak reference), not of a predefined macro: clang 14 (Debian 12) does not define
// __SANITIZE_ADDRESS__, so a macro guard left the children with leak detection on.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

extern "C" void __asan_init() __attribute__((weak));

namespace {

bool addressSanitizerRuns() { return &__asan_init != nullptr; }

const char* const kLeaksOff = "detect_leaks=0";

// Before main: the children inherit the environment; this process parsed its options already.
const bool childrenWithoutLeakCheck = [] {
    if (!addressSanitizerRuns()) return false;
    const char* options = std::getenv("ASAN_OPTIONS");
    const std::string withLeaksOff = std::string(options ? options : "") + (options && *options ? ":" : "") + kLeaksOff;
    return ::setenv("ASAN_OPTIONS", withLeaksOff.c_str(), 1) == 0;
}();

}  // namespace

// Under AddressSanitizer the environment the children inherit ends with leak detection off
// (the last setting of an option wins); without it, the environment is left as it was.
TEST(ChildSanitizerOptions, ChildrenInheritLeakDetectionOffUnderAddressSanitizer) {
    const char* options = std::getenv("ASAN_OPTIONS");
    const std::string value = options ? options : "";
    const bool endsWithLeaksOff =
        value.size() >= std::string(kLeaksOff).size() &&
        value.compare(value.size() - std::string(kLeaksOff).size(), std::string::npos, kLeaksOff) == 0;
    if (addressSanitizerRuns()) {
        EXPECT_TRUE(childrenWithoutLeakCheck);
        EXPECT_TRUE(endsWithLeaksOff) << "ASAN_OPTIONS=" << value;
    } else {
        EXPECT_FALSE(childrenWithoutLeakCheck);
    }
}
