// The stats overlay (top left of the viewport; the 3D viewport's or the 2D view's), the error
// banners and the status line (bottom of the viewport).
#include <imgui.h>

#include <algorithm>
#include <regex>

#include "app/editor/panels/panels.hpp"

namespace fraktal::editor {

namespace {
constexpr ImGuiWindowFlags kOverlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                           ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;

// The node a compile log names, as the node list shows it (`node 2 "Box fold"`), or empty.
std::string nodeInLog(const std::string& log) {
    std::smatch m;
    if (std::regex_search(log, m, std::regex(R"(((start )?node \d+|estimator) "[^"]*")"))) return m[0];
    return "";
}

// Banners over the viewport: a compile error (the last good image stays) and a display error.
// They sit at the bottom of the viewport, never in front of a window, and let clicks through, so
// they hide no control (the GLSL block editor's close button included).
void drawErrorBanners(const Layout& l, const std::string& compileError, const std::string& displayError) {
    constexpr ImGuiWindowFlags kBannerFlags =
        kOverlayFlags | ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoBringToFrontOnFocus;
    if (!compileError.empty()) {
        ImGui::SetNextWindowPos(ImVec2(l.viewportX + l.viewportW * 0.5f, l.viewportY + l.viewportH - 80),
                                ImGuiCond_Always, ImVec2(0.5f, 1));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("##compile_error", nullptr, kBannerFlags);
        const std::string node = nodeInLog(compileError);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "Compile error%s%s: showing the last good image.",
                           node.empty() ? "" : " in ", node.c_str());
        ImGui::TextDisabled("Details under the node in the Formula panel.");
        ImGui::End();
    }
    if (!displayError.empty()) {
        ImGui::SetNextWindowPos(ImVec2(l.viewportX + l.viewportW * 0.5f, l.viewportY + l.viewportH - 40),
                                ImGuiCond_Always, ImVec2(0.5f, 1));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("##display_error", nullptr, kBannerFlags);
        ImGui::PushTextWrapPos(l.viewportW * 0.8f);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "Display: %s", displayError.c_str());
        ImGui::PopTextWrapPos();
        ImGui::End();
    }
}

// The error banners, then (when shown) the stats window at the viewport's top left: true when
// the caller fills it (and ends it).
bool beginStatsOverlay(EditorState& s, const std::string& compileError, const std::string& displayError) {
    const Layout& l = s.layout;
    drawErrorBanners(l, compileError, displayError);
    if (!s.panels.stats) return false;
    ImGui::SetNextWindowPos(ImVec2(l.viewportX + 10, l.viewportY + 10), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("##stats", nullptr, kOverlayFlags);
    return true;
}

// Frames per second and milliseconds per frame, both from ImGui's smoothed frame rate (the mean
// of its last 120 frame times), so they always agree: fps = 1000 / ms.
void frameRateLine() {
    const float fps = ImGui::GetIO().Framerate;
    ImGui::Text("%.1f fps   %.1f ms / frame", fps, 1000.0f / std::max(fps, 1e-3f));
}

}  // namespace

void drawStatsOverlay(EditorState& s, const ViewportView& v) {
    if (!beginStatsOverlay(s, v.compileError(), v.displayError())) return;
    // The viewport's own per-frame statistics (core/viewport FrameStats).
    const ViewportStats& st = v.stats();
    frameRateLine();
    const char* cameraMode = s.cameraControls.mode == CameraMode::Fly ? "FLY" : "ORBIT";
    if (st.pathTracing) {  // the fast mode's figures belong to the last fast frame: not shown
        ImGui::Text("%d x %d px   %.0f ms of samples", st.width, st.height, st.renderMs);
        ImGui::Text("path traced %d / %d spp%s   %s", st.pathSamples, st.pathSppCap, st.settled ? " (settled)" : "",
                    cameraMode);
    } else {
        ImGui::Text("%d x %d px   %.1f DE evals / px", st.width, st.height, st.deEvaluationsPerPixel);
        ImGui::Text("internal scale %.2f%s", st.internalScale, st.internalScale < 1.0 ? " (moving)" : "");
        ImGui::Text("reprojected %.0f%%   converged %.0f%%", 100.0 * st.reprojectedShare, 100.0 * st.convergedShare);
        ImGui::Text("AA %d / %d spp%s   %s", st.aaLevel, st.aaCap, st.settled ? " (settled)" : "", cameraMode);
    }
    if (st.compiling) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.3f, 1.0f), "compiling the new structure...");
    ImGui::End();
}

void drawPlaneStatsOverlay(EditorState& s, const PlaneViewport& v) {
    if (!beginStatsOverlay(s, v.compileError(), v.displayError())) return;
    const PlaneViewportStats& st = v.stats();
    frameRateLine();
    ImGui::Text("%d x %d px   %s", st.width, st.height, st.fp64 ? "fp64" : "fp32");
    ImGui::Text("samples %d / %d spp%s   2D", st.samples, st.target, st.samples >= st.target ? " (settled)" : "");
    if (s.doc.plane) ImGui::Text("view width %.3g", s.doc.plane->view.width);
    for (const std::string& w : v.warnings()) ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.4f, 1), "%s", w.c_str());
    ImGui::End();
}

void drawStatusLine(EditorState& s) {
    if (s.status.text.empty() || s.now > s.status.until) return;
    const Layout& l = s.layout;
    ImGui::SetNextWindowPos(ImVec2(l.viewportX + 10, l.viewportY + l.viewportH - 10), ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("##status", nullptr, kOverlayFlags);
    ImGui::PushTextWrapPos(l.viewportW - 40);
    if (s.status.error)
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "%s", s.status.text.c_str());
    else
        ImGui::TextUnformatted(s.status.text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace fraktal::editor
