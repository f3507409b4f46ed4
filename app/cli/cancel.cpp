#include "cli/cancel.hpp"

#include <csignal>

namespace fraktal::cli {

namespace {
std::atomic<bool> gCancelRequested{false};
extern "C" void requestCancel(int) { gCancelRequested.store(true); }
}  // namespace

const std::atomic<bool>& cancelOnSignal() {
    gCancelRequested = false;
    std::signal(SIGINT, requestCancel);
    std::signal(SIGTERM, requestCancel);
    return gCancelRequested;
}

}  // namespace fraktal::cli
