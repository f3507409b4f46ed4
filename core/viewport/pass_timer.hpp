// GPU time of each viewport pass, from GL timestamp queries (glQueryCounter(GL_TIMESTAMP)) placed
// between the passes of one frame. Off by default (ViewportOptions::timePasses): reading the
// queries back waits for the frame. On llvmpipe compute dispatches run when issued, so the
// timestamps bracket each pass; on a real GPU they are the GPU's own clock.
#pragma once

#include <epoxy/gl.h>

#include <vector>

#include "core/viewport/frame_logic.hpp"

namespace fraktal::viewport {

class PassTimer {
   public:
    PassTimer();
    ~PassTimer();
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    void begin();                 // starts a frame: the first timestamp
    void mark(const char* pass);  // the pass named `pass` ends here
    // Milliseconds of each marked pass, in order; waits for the queries.
    std::vector<PassTime> read();

   private:
    static constexpr int kMaxMarks = 16;
    GLuint queries_[kMaxMarks + 1] = {};
    const char* names_[kMaxMarks] = {};
    int marks_ = 0;
};

}  // namespace fraktal::viewport
