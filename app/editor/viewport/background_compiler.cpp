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

void BackgroundCompiler::requestGrid(const GridSize& size) {
    {
        std::lock_guard lock(mutex_);
        if (size == gridRequested_) return;
        gridRequested_ = size;
        gridQueued_ = size;
    }
    wake_.notify_one();
}

std::unique_ptr<viewport::MarchState> BackgroundCompiler::takeGrid() {
    std::lock_guard lock(mutex_);
    if (!gridDone_) return nullptr;
    // Taken: the viewport may need one of this size again after a resize. A grid of a size asked
    // for before leaves the newer request standing.
    if (GridSize{gridDone_->width(), gridDone_->height(), gridDone_->coneTile()} == gridRequested_)
        gridRequested_ = GridSize{};
    return std::move(gridDone_);
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
        wake_.wait(lock, [this] { return stop_ || queued_ || gridQueued_; });
        if (stop_) break;
        if (gridQueued_ && unavailable.empty()) {
            const GridSize size = *gridQueued_;
            gridQueued_.reset();
            lock.unlock();
            auto grid = std::make_unique<viewport::MarchState>(size.width, size.height, size.coneTile);
            grid->touchAll();
            glFinish();  // complete before the editor's context uses it
            lock.lock();
            gridDone_ = std::move(grid);  // replaces (deletes here) one not taken
            continue;
        }
        gridQueued_.reset();
        if (!queued_) continue;
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
    gridDone_.reset();
    lock.unlock();
    if (unavailable.empty()) unbind_();
}

}  // namespace fraktal::editor
