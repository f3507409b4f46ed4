#include "core/viewport/gpu_counters.hpp"

#include <array>

namespace fraktal::viewport {

namespace {
constexpr int kCounters = 6;  // deEvals, reprojected, converged, shaded, busy, shadeDeEvals
}

GpuCounters::GpuCounters() {
    glCreateBuffers(1, &buffer_);
    glNamedBufferStorage(buffer_, kCounters * sizeof(uint32_t), nullptr, GL_DYNAMIC_STORAGE_BIT | GL_MAP_READ_BIT);
}

GpuCounters::~GpuCounters() { glDeleteBuffers(1, &buffer_); }

void GpuCounters::clearAndBind() {
    const std::array<uint32_t, kCounters> zeros{};
    glNamedBufferSubData(buffer_, 0, sizeof zeros, zeros.data());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, buffer_);
}

FrameCounters GpuCounters::read() const {
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::array<uint32_t, kCounters> v{};
    glGetNamedBufferSubData(buffer_, 0, sizeof v, v.data());
    busy_ = v[4];
    return FrameCounters{v[0], v[1], 0, v[2], v[3], v[5]};
}

}  // namespace fraktal::viewport
