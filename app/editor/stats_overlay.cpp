// The stats overlay (top left of the viewport) and the status line (bottom of the viewport).
#include <imgui.h>

#include "app/editor/panels.hpp"

namespace fraktal::editor {

namespace {
constexpr ImGuiWindowFlags kOverlayFlags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                           ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                           ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
}

void drawStatsOverlay(EditorState& s, const ViewportView& v) {
    const Layout& l = s.layout;
    if (!v.compileError().empty()) {
        ImGui::SetNextWindowPos(ImVec2(l.viewportX + l.viewportW * 0.5f, l.viewportY + 10), ImGuiCond_Always,
                                ImVec2(0.5f, 0));
        ImGui::SetNextWindowBgAlpha(0.85f);
        ImGui::Begin("##compile_error", nullptr, kOverlayFlags);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "Compile error: showing the last good image.");
        ImGui::TextDisabled("Details under the node in the Formula panel.");
        ImGui::End();
    }
    if (!s.panels.stats) return;
    const ViewportStats& st = v.stats();
    const ImGuiIO& io = ImGui::GetIO();
    ImGui::SetNextWindowPos(ImVec2(l.viewportX + 10, l.viewportY + 10), ImGuiCond_Always);
    ImGui::SetNextWindowBgAlpha(0.55f);
    ImGui::Begin("##stats", nullptr, kOverlayFlags);
    ImGui::Text("%.0f fps  (%.1f ms UI, %.1f ms render)", io.Framerate, 1000.0f / std::max(io.Framerate, 1e-3f),
                st.renderMs);
    ImGui::Text("%d x %d px, %.1f DE evals / px", st.width, st.height, st.deEvaluationsPerPixel);
    ImGui::Text("AA %d / %d spp   converged %.0f%%   reused %.0f%%", st.samples, st.aaCap, 100.0 * st.convergedShare,
                100.0 * st.reprojectedShare);
    ImGui::Text("hit %.0f%%   compiles %d   %s", 100.0 * st.hitShare, st.compiles,
                s.cameraControls.mode == CameraMode::Fly ? "FLY" : "ORBIT");
    ImGui::End();
}

void drawStatusLine(EditorState& s) {
    if (s.status.text.empty() || s.now > s.status.until) return;
    const Layout& l = s.layout;
    ImGui::SetNextWindowPos(ImVec2(l.viewportX + 10, l.viewportY + l.viewportH - 10), ImGuiCond_Always, ImVec2(0, 1));
    ImGui::SetNextWindowBgAlpha(0.7f);
    ImGui::Begin("##status", nullptr, kOverlayFlags);
    ImGui::PushTextWrapPos(l.viewportW - 40);
    if (s.status.error) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1), "%s", s.status.text.c_str());
    else ImGui::TextUnformatted(s.status.text.c_str());
    ImGui::PopTextWrapPos();
    ImGui::End();
}

}  // namespace fraktal::editor
