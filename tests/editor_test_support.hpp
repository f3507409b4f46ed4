// Helpers shared by the tests of the editor's logic (app/editor): a document from a shipped preset,
// the export job polled as the frame loop polls it.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/editor/document/document.hpp"
#include "app/editor/document/export_job.hpp"
#include "app/editor/document/formula_edits.hpp"
#include "test_support.hpp"

namespace fraktal::test {

// A document holding the shipped 3D preset `name` ("mandelbulb.json").
inline editor::Document documentFrom(const char* name) {
    editor::Document d;
    d.preset = shippedPreset(name);
    return d;
}

// Runs `frame` (one of the editor's frames) every 10 ms while `busy` holds, for at most `seconds`
// (a deadline, not a count of frames: under the sanitizers a step-factor measurement takes
// minutes); then one frame more. False if `busy` still holds.
template <class Busy, class Frame>
bool framesWhile(Busy busy, Frame frame, double seconds = 600.0) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (busy() && std::chrono::steady_clock::now() < end) {
        frame();
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    frame();
    return !busy();
}

// AutoStepFactor::update as the editor's frames call it, until it applies a measurement (a new
// structure's settled rounds run on a worker) or has nothing to measure: what that frame's update
// returned.
inline bool updateUntilMeasured(editor::AutoStepFactor& a, Formula& f, const Camera& camera) {
    bool applied = a.update(f, camera);
    framesWhile([&] { return !applied && a.measuring(); }, [&] { applied = applied || a.update(f, camera); });
    return applied;
}

// Polls like the editor's frame loop does until the job ends; false on timeout.
inline bool pollUntilEnded(editor::ExportProcess& job, double seconds) {
    const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
    while (editor::exportActive(job)) {
        if (std::chrono::steady_clock::now() > end) return false;
        editor::pollExport(job);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return true;
}

// Cancels a running job as the dialog's button does: the call returns at once (the UI thread
// does not wait for the child) and the job is Cancelling, then Cancelled within `seconds`.
inline void expectCancelReturnsAtOnce(editor::ExportProcess& job, double seconds) {
    const auto before = std::chrono::steady_clock::now();
    editor::cancelExport(job);
    EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count(), 0.1)
        << "the UI thread does not wait for the child";
    EXPECT_EQ(job.status, editor::ExportStatus::Cancelling);
    ASSERT_TRUE(pollUntilEnded(job, seconds)) << job.log;
    EXPECT_EQ(job.status, editor::ExportStatus::Cancelled) << job.log;
}

}  // namespace fraktal::test
