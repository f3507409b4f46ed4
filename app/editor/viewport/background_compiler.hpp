// Structure edits compile off the UI thread: the viewport's programs for a new formula
// structure are built on a worker thread whose GL context shares objects with the editor's (GL
// programs are shared objects), so the window keeps drawing the last good image meanwhile. Only
// the newest requested structure matters: requests made while one compiles replace the queued one.
// The same worker makes the viewport's grid for a new size ahead (its memory written once there),
// before any compile waiting: the first frame at full size after opening had spent 60 ms on it.
//
// The context is the caller's business (the editor makes a hidden GLFW window sharing its
// context); this class only calls `bind` once on the worker before compiling and `unbind` when it
// stops. Destroy it while the editor's context still exists.
#pragma once

#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "core/formula.hpp"
#include "core/viewport/march_state.hpp"
#include "core/viewport/viewport_programs.hpp"
#include "core/viewport/warm_up.hpp"

namespace fraktal::editor {

class BackgroundCompiler {
   public:
    struct Result {
        std::string structure;                                 // Formula::structureKey() of what was compiled
        std::unique_ptr<viewport::ViewportPrograms> programs;  // null when it failed
        std::string error;  // the compile log naming the node (explainLog) when it failed
    };

    // `frames`: which passes the programs' viewport runs, whose machine code the worker gets
    // before handing them over (core/viewport/warm_up.hpp).
    BackgroundCompiler(std::function<void()> bind, std::function<void()> unbind,
                       viewport::WarmUpFrames frames = viewport::WarmUpFrames::StillAndMotion);
    ~BackgroundCompiler();
    BackgroundCompiler(const BackgroundCompiler&) = delete;
    BackgroundCompiler& operator=(const BackgroundCompiler&) = delete;

    // Starts compiling this formula's structure unless it is the one queued, compiling or done.
    void request(const Formula& formula);
    // The finished result for this structure, once (nullopt while it compiles or for another).
    std::optional<Result> take(const std::string& structure);

    // A march grid of this size and cone tile, made on the worker unless it is the one asked for
    // last; takeGrid hands over the last one made, whatever its size (null while none is), so
    // that the caller frees one it no longer wants.
    struct GridSize {
        int width = 0, height = 0, coneTile = 0;
        bool operator==(const GridSize&) const = default;
    };
    void requestGrid(const GridSize& size);
    std::unique_ptr<viewport::MarchState> takeGrid();

   private:
    void work();

    std::function<void()> bind_, unbind_;
    viewport::WarmUpFrames frames_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Formula> queued_;
    std::string requested_;  // the newest structure asked for
    std::optional<Result> done_;
    std::optional<GridSize> gridQueued_;
    GridSize gridRequested_;
    std::unique_ptr<viewport::MarchState> gridDone_;
    bool stop_ = false;
    std::thread worker_;  // last: starts after every member above exists
};

}  // namespace fraktal::editor
