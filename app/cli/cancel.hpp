// Ctrl+C (SIGINT) and SIGTERM ask a long command (render, encode) to stop at its next safe point,
// so that it can remove its temporary files and leave every destination as it was. The default
// action would end the process at once and leave the temporary file behind.
#pragma once

#include <atomic>

namespace fraktal::cli {

// Clears the request and routes SIGINT and SIGTERM to it; returns the flag to poll. A signal
// handler can only reach global state, so there is one flag for the process.
const std::atomic<bool>& cancelOnSignal();

// The exit status of a command stopped by SIGINT (128 + 2, as a shell reports it).
inline constexpr int kCancelledExitCode = 130;

}  // namespace fraktal::cli
