#include "app/editor/viewport/background_compiler.hpp"

#include <stdexcept>

namespace fraktal::editor {

BackgroundCompiler::BackgroundCompiler(std::function<void()> bind, std::function<void()> unbind,
                                       viewport::WarmUpFrames frames)
    : bind_(std::move(bind)), unbind_(std::move(unbind)), frames_(frames), worker_([this] { work(); }) {}

BackgroundCompiler::~BackgroundCompiler() {
    {
        std::lock_guard lock(mutex_);
        stop_ = true;
    }
    wake_.notify_one();
    worker_.join();
}

void BackgroundCompiler::request(const Formula& formula) {
    std::string structure = formula.structureKey();
    {
        std::lock_guard lock(mutex_);
        if (structure == requested_) return;
        requested_ = std::move(structure);
        queued_ = formula;  // shares the custom blocks (immutable) with the caller's formula
    }
    wake_.notify_one();
}

std::optional<BackgroundCompiler::Result> BackgroundCompiler::take(const std::string& structure) {
    std::lock_guard lock(mutex_);
    if (!done_ || done_->structure != structure) return std::nullopt;
    std::optional<Result> result = std::move(done_);
    done_.reset();
    requested_.clear();  // taken: asking again (e.g. after an undo) compiles again
    return result;
}

void BackgroundCompiler::work() {
    std::string unavailable;  // why this thread has no GL context (each request then fails with it)
    try {
        bind_();
    } catch (const std::exception& e) {
        unavailable = std::string("background compiler: ") + e.what();
    }
    std::unique_lock lock(mutex_);
    for (;;) {
        wake_.wait(lock, [this] { return stop_ || queued_; });
        if (stop_) break;
        const Formula formula = std::move(*queued_);
        queued_.reset();
        lock.unlock();
        Result result;
        result.structure = formula.structureKey();
        try {
            if (!unavailable.empty()) throw std::runtime_error(unavailable);
            result.programs = std::make_unique<viewport::ViewportPrograms>(formula);
            // Their machine code too, here rather than in the main thread's first frame.
            result.programs = viewport::warmUp(std::move(result.programs), formula, frames_);
            glFinish();  // complete before another context uses the programs
        } catch (const std::exception& e) {
            result.error = e.what();
        }
        lock.lock();
        // A newer request may be queued already; this result is still kept until replaced, and a
        // superseded one is dropped here (deleting its programs on this shared context).
        done_ = std::move(result);
    }
    done_.reset();
    lock.unlock();
    if (unavailable.empty()) unbind_();
}

}  // namespace fraktal::editor
