// Helpers shared by the tests of the editor's export job (app/editor/document/export_job.hpp).
#pragma once

#include <chrono>
#include <thread>

#include "app/editor/document/export_job.hpp"

namespace fraktal::test {

// Polls like the editor's frame loop does until the job ends; false on timeout.
inline bool pollUntilEnded(editor::ExportJob& job, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (editor::exportActive(job)) {
        if (std::chrono::steady_clock::now() > end) return false;
        editor::pollExport(job);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

}  // namespace fraktal::test
