// The camera's keyed path over the viewport: the position track sampled at every frame (at the
// camera's time, so an even-speed path is drawn where the camera goes), projected through the
// current camera with a pinhole model as the renderer's rays (core/camera.hpp: rayDirection).
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "app/editor/timeline/timeline_panel.hpp"

namespace fraktal::editor {

namespace {

constexpr int kMaxSamples = 2000;
constexpr ImU32 kPathColor = IM_COL32(90, 200, 255, 230);
constexpr ImU32 kKeyDotColor = IM_COL32(255, 220, 80, 255);

struct Projected {
    ImVec2 at;
    bool visible = false;  // in front of the camera
};

Projected project(const Camera& camera, const CameraBasis& b, const vec3& p, const Layout& l) {
    const vec3 d = p - camera.position;
    const double z = dot(d, b.forward);
    if (z < 1e-4) return {};
    const double tanHalf = camera.tanHalfFovY(), aspect = double(l.viewportW) / std::max(double(l.viewportH), 1.0);
    const double ndcX = dot(d, b.right) / (z * tanHalf * aspect), ndcY = dot(d, b.up) / (z * tanHalf);
    return {ImVec2(l.viewportX + float((ndcX + 1.0) / 2.0) * l.viewportW,
                   l.viewportY + float((1.0 - ndcY) / 2.0) * l.viewportH),
            true};
}

vec3 asVec(const std::vector<double>& v) { return vec3(v[0], v[1], v[2]); }

}  // namespace

void drawCameraPathOverlay(const EditorState& s) {
    if (!s.timeline.showCameraPath || s.doc.plane) return;
    const Animation& a = s.doc.preset.animation;
    const Track* path = findTrack(a, "camera.position");
    if (!path) return;
    const Layout& l = s.layout;
    const Camera& camera = s.doc.preset.camera;
    const CameraBasis b = camera.basis();
    ImDrawList* dl = ImGui::GetBackgroundDrawList();
    dl->PushClipRect(ImVec2(l.viewportX, l.viewportY), ImVec2(l.viewportX + l.viewportW, l.viewportY + l.viewportH),
                     true);
    const int first = a.firstFrame, last = shownLastFrame(a);
    const int samples = std::clamp(last - first, 1, kMaxSamples);
    Projected previous;
    for (int i = 0; i <= samples; ++i) {
        const double frame = first + double(last - first) * i / samples;
        const Projected p = project(camera, b, asVec(evaluateTrack(*path, cameraTime(a, frame))), l);
        if (p.visible && previous.visible) dl->AddLine(previous.at, p.at, kPathColor, 2.0f);
        previous = p;
    }
    for (const Key& k : path->keys)
        if (const Projected p = project(camera, b, asVec(k.value), l); p.visible)
            dl->AddCircleFilled(p.at, 4.5f, kKeyDotColor);
    dl->PopClipRect();
}

}  // namespace fraktal::editor
