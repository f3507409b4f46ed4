#include "app/editor/viewport/frame_log.hpp"

#include <cerrno>
#include <cstring>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace fraktal::editor {

void openFrameLog(FrameLog& log, const std::filesystem::path& path) {
    closeFrameLog(log);
    log.file = std::fopen(path.c_str(), "w");
    if (!log.file) throw std::runtime_error(path.string() + ": cannot write the frame log: " + std::strerror(errno));
}

void logFrame(FrameLog& log, double now, const ViewportStats& stats, const Camera& camera, const float viewport[4],
              UiDraw ui, bool thumbnails, const FramePhases& phases) {
    if (!log.file) return;
    const double frameMs = log.lastFrameAt < 0.0 ? 0.0 : (now - log.lastFrameAt) * 1000.0;
    log.lastFrameAt = now;
    auto vec = [](const vec3& v) { return nlohmann::json::array({v.x, v.y, v.z}); };
    const nlohmann::json line = {{"t", now},
                                 {"frame_ms", frameMs},
                                 {"render_ms", stats.renderMs},
                                 {"steps_per_frame", stats.stepsPerFrame},
                                 {"slices", stats.slices},
                                 {"scale", stats.internalScale},
                                 {"width", stats.width},
                                 {"height", stats.height},
                                 {"settled", stats.settled},
                                 {"action", stats.action},
                                 {"ui", uiDrawName(ui)},
                                 {"thumbnails", thumbnails},
                                 {"phases",
                                  {{"events_ms", phases.eventsMs},
                                   {"panels_ms", phases.panelsMs},
                                   {"draw_ms", phases.drawMs},
                                   {"swap_ms", phases.swapMs},
                                   {"after_ms", phases.afterMs}}},
                                 {"viewport", {viewport[0], viewport[1], viewport[2], viewport[3]}},
                                 {"camera",
                                  {{"position", vec(camera.position)},
                                   {"target", vec(camera.target)},
                                   {"up", vec(camera.up)},
                                   {"fovY", camera.fovY}}}};
    std::fprintf(log.file, "%s\n", line.dump().c_str());
    std::fflush(log.file);
}

void closeFrameLog(FrameLog& log) {
    if (log.file) std::fclose(log.file);
    log.file = nullptr;
}

}  // namespace fraktal::editor
