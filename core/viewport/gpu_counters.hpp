// The frame statistics buffer the viewport passes add to (ViewportCounters in
// shaders/viewport_common.glsl).
#pragma once

#include <epoxy/gl.h>

#include "core/viewport/frame_logic.hpp"

namespace fraktal::viewport {

class GpuCounters {
   public:
    GpuCounters();
    ~GpuCounters();
    GpuCounters(const GpuCounters&) = delete;
    GpuCounters& operator=(const GpuCounters&) = delete;

    void clearAndBind();  // zeroes the counters and binds them at SSBO binding 0
    // Waits for the frame's passes. FrameCounters::restarted is left 0: the passes do not count it.
    FrameCounters read() const;
    uint32_t busyPixels() const { return busy_; }

   private:
    GLuint buffer_ = 0;
    mutable uint32_t busy_ = 0;
};

}  // namespace fraktal::viewport
