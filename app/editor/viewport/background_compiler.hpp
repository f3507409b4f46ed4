// Structure edits compile off the UI thread: the viewport's programs for a new formula
// structure are built on a worker thread whose GL context shares objects with the editor's (GL
// programs are shared objects), so the window keeps drawing the last good image meanwhile. Only
// the newest requested structure matters: requests made while one compiles replace the queued one.
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

   private:
    void work();

    std::function<void()> bind_, unbind_;
    viewport::WarmUpFrames frames_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::optional<Formula> queued_;
    std::string requested_;  // the newest structure asked for
    std::optional<Result> done_;
    bool stop_ = false;
    std::thread worker_;  // last: starts after every member above exists
};

}  // namespace fraktal::editor
