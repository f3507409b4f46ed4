// The timeline panel: play / pause, loop, the current frame, the animation's frame range and fps,
// a scrub bar with frame numbers, and a row of keys per track (click a key to select it, drag it
// to move it, Delete removes it; right-click a track's name for its interpolation). Also the key
// markers the parameter widgets draw beside themselves.
#include "app/editor/timeline/timeline_panel.hpp"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/editor/state/actions.hpp"
#include "app/editor/viewport/camera_input.hpp"
#include "app/editor/widgets/item_rects.hpp"
#include "app/editor/widgets/param_widgets.hpp"

namespace fraktal::editor {

namespace {

constexpr float kLabelWidth = 130.0f;  // track names left of the bar
constexpr float kRulerHeight = 18.0f;
constexpr float kRowHeight = 16.0f;
constexpr int kMaxRowsShown = 6;
constexpr float kKeyRadius = 5.0f;
constexpr ImU32 kKeyColor = IM_COL32(235, 200, 70, 255);
constexpr ImU32 kChangedColor = IM_COL32(255, 140, 40, 255);
constexpr ImU32 kUnkeyedColor = IM_COL32(140, 140, 140, 200);
constexpr ImU32 kSelectedColor = IM_COL32(255, 255, 255, 255);
constexpr ImU32 kPlayheadColor = IM_COL32(230, 70, 60, 255);

void diamond(ImDrawList* dl, ImVec2 c, float r, ImU32 color, bool filled) {
    const ImVec2 a(c.x, c.y - r), b(c.x + r, c.y), d(c.x, c.y + r), e(c.x - r, c.y);
    if (filled)
        dl->AddQuadFilled(a, b, d, e, color);
    else
        dl->AddQuad(a, b, d, e, color, 1.5f);
}

bool consume(EditorState& s, int key) {
    const auto it = std::find_if(s.keyPresses.begin(), s.keyPresses.end(),
                                 [&](const KeyPress& p) { return p.key == key && p.mods == 0; });
    if (it == s.keyPresses.end()) return false;
    s.keyPresses.erase(it);
    return true;
}

void startPlaying(EditorState& s) {
    TimelineState& t = s.timeline;
    const Animation& a = s.doc.preset.animation;
    if (!t.loop && t.frame >= shownLastFrame(a)) t.frame = a.firstFrame;
    t.playing = true;
    t.playStartTime = s.now;
    t.playStartFrame = t.frame;
}

// The animation with the range the timeline shows (a still's default span).
Animation shownAnimation(const Animation& a) {
    Animation shown = a;
    shown.lastFrame = shownLastFrame(a);
    return shown;
}

// Writes the animation at the timeline's frame into the document and into the undo history's
// present state, so that showing another frame is no undo step, and a document that was saved
// stays saved.
void showFrame(EditorState& s) {
    TimelineState& t = s.timeline;
    const bool clean = !isDirty(s);
    applyAnimationFrame(s.doc.preset, t.frame);
    Document present = s.history.present();
    applyAnimationFrame(present.preset, t.frame);
    s.history.replacePresent(present);
    if (clean) s.file.savedFingerprint = fingerprint(s.doc);
    t.appliedFrame = t.frame;
    t.appliedAnimation = s.doc.preset.animation;
}

// A key edit from the UI: the first key of a still extends its range to the span shown.
void addKeyHere(EditorState& s, const std::string& target, const std::vector<double>& value) {
    Animation& a = s.doc.preset.animation;
    if (a.empty() && a.lastFrame <= a.firstFrame) a.lastFrame = shownLastFrame(a);
    addKey(a, target, s.timeline.frame, value);
}

void interpolationItems(EditorState& s, const std::string& target) {
    const Track* track = findTrack(s.doc.preset.animation, target);
    if (!track) return;
    ImGui::Separator();
    if (stepsAtKeys(s.doc.preset, target)) {
        ImGui::TextDisabled("On/off: steps at each key");
        return;
    }
    const char* names[] = {"Constant", "Linear", "Smooth"};
    for (int i = 0; i < 3; ++i)
        if (ImGui::MenuItem(names[i], nullptr, int(track->interpolation) == i))
            setInterpolation(s.doc.preset.animation, target, Interpolation(i));
    if (target == "camera.position") {
        bool even = s.doc.preset.animation.evenCameraSpeed;
        if (ImGui::MenuItem("Even camera speed", nullptr, &even)) s.doc.preset.animation.evenCameraSpeed = even;
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("Re-times the camera so that it moves at a constant speed along its path.");
    }
}

void controlsRow(EditorState& s) {
    TimelineState& t = s.timeline;
    Animation& a = s.doc.preset.animation;
    const ImVec2 at = ImGui::GetCursorScreenPos();
    if (ImGui::Button(t.playing ? "Pause" : "Play", ImVec2(52, 0))) {
        if (t.playing)
            t.playing = false;
        else
            startPlaying(s);
    }
    t.playButton[0] = at.x + 26;
    t.playButton[1] = at.y + ImGui::GetFrameHeight() / 2;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Space over the viewport or the timeline");
    ImGui::SameLine();
    ImGui::Checkbox("Loop", &t.loop);
    const float field = 44.0f;
    const auto label = [](const char* text) {
        ImGui::SameLine();
        ImGui::TextUnformatted(text);
        ImGui::SameLine(0, 4);
    };
    label("Frame");
    ImGui::SetNextItemWidth(field);
    int frame = t.frame;
    if (inputClamped("##frame", &frame, 0, 0, a.firstFrame, shownLastFrame(a), "Frame")) {
        t.frame = frame;
        t.playing = false;
    }
    noteItemRect(s.layout.widgetRects, "timeline:Frame");
    label("Start");
    ImGui::SetNextItemWidth(field);
    int first = a.firstFrame, last = shownLastFrame(a);
    if (inputClamped("##start", &first, 0, 0, 0, last, "Start")) a.firstFrame = first;
    noteItemRect(s.layout.widgetRects, "timeline:Start");
    label("End");
    ImGui::SetNextItemWidth(field);
    if (inputClamped("##end", &last, 0, 0, a.firstFrame, 10000000, "End")) a.lastFrame = last;
    noteItemRect(s.layout.widgetRects, "timeline:End");
    label("fps");
    ImGui::SetNextItemWidth(field);
    double fps = a.fps;
    if (inputClamped("##fps", &fps, 1e-3, 1000.0, "%.4g", "fps")) a.fps = fps;
    noteItemRect(s.layout.widgetRects, "timeline:fps");
    ImGui::SameLine();
    const ImVec2 pathAt = ImGui::GetCursorScreenPos();
    ImGui::Checkbox("Path", &t.showCameraPath);
    t.pathButton[0] = pathAt.x + ImGui::GetFrameHeight() / 2;
    t.pathButton[1] = pathAt.y + ImGui::GetFrameHeight() / 2;
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Draw the camera's path in the viewport (View > Camera path)");
}

// Frame numbers every 1, 2, 5, 10, 20, 50, ... frames, at least 40 pixels apart.
int tickStep(double pixelsPerFrame) {
    for (int step = 1;; step *= 10)
        for (int m : {1, 2, 5})
            if (step * m * pixelsPerFrame >= 40.0 || step > 1000000) return step * m;
}

// The track rows and the scrub bar; returns the key under the pointer on a press.
void scrubBar(EditorState& s) {
    TimelineState& t = s.timeline;
    Animation& a = s.doc.preset.animation;
    const int first = a.firstFrame, last = shownLastFrame(a);
    t.shownFirst = first;
    t.shownLast = last;
    ImDrawList* dl = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float width = ImGui::GetContentRegionAvail().x;
    const int trackCount = int(a.tracks.size());
    const int rows = std::max(1, std::min(trackCount, kMaxRowsShown));
    // More tracks than rows: the mouse wheel over the timeline scrolls through them.
    t.firstRow = std::clamp(t.firstRow, 0, std::max(0, trackCount - rows));
    const auto trackOfRow = [&](int r) -> Track* {
        const int i = t.firstRow + r;
        return r < rows && i < trackCount ? &a.tracks[size_t(i)] : nullptr;
    };
    const ImVec2 barMin(origin.x + kLabelWidth, origin.y);
    const float barW = std::max(width - kLabelWidth - kKeyRadius, 10.0f);
    const float barH = kRulerHeight + rows * kRowHeight;
    t.bar[0] = barMin.x;
    t.bar[1] = barMin.y;
    t.bar[2] = barW;
    t.bar[3] = barH;
    const double span = std::max(last - first, 1);
    const auto xOf = [&](double f) { return barMin.x + float((f - first) / span) * barW; };
    const auto frameAt = [&](float x) {
        return std::clamp(int(std::lround(first + (x - barMin.x) / barW * span)), first, last);
    };

    // Track names, each with its interpolation on a right click.
    for (int r = 0; trackOfRow(r); ++r) {
        const Track& track = *trackOfRow(r);
        const float y = origin.y + kRulerHeight + r * kRowHeight;
        ImGui::SetCursorScreenPos(ImVec2(origin.x, y));
        ImGui::PushID(r);
        const std::string name = targetLabel(s.doc.preset, track.target);
        ImGui::InvisibleButton("track", ImVec2(kLabelWidth - 4, kRowHeight));
        const char interp = "CLS"[int(interpolationIn(s.doc.preset, track))];
        dl->PushClipRect(ImVec2(origin.x, y), ImVec2(origin.x + kLabelWidth - 4, y + kRowHeight), true);
        dl->AddText(ImVec2(origin.x, y), ImGui::GetColorU32(ImGuiCol_Text),
                    (std::string(1, interp) + " " + name).c_str());
        dl->PopClipRect();
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s (%s): right-click for the interpolation", name.c_str(), track.target.c_str());
        if (ImGui::BeginPopupContextItem("track_menu")) {
            const std::string target = track.target;  // the menu may change the track list
            interpolationItems(s, target);
            ImGui::EndPopup();
        }
        ImGui::PopID();
    }

    // Ruler, rows and playhead.
    const ImVec2 barMax(barMin.x + barW, barMin.y + barH);
    dl->AddRectFilled(barMin, barMax, IM_COL32(30, 32, 36, 255));
    dl->AddRectFilled(barMin, ImVec2(barMax.x, barMin.y + kRulerHeight), IM_COL32(40, 43, 48, 255));
    const int step = tickStep(barW / span);
    for (int f = (first + step - 1) / step * step; f <= last; f += step) {
        const float x = xOf(f);
        dl->AddLine(ImVec2(x, barMin.y + kRulerHeight - 5), ImVec2(x, barMax.y), IM_COL32(70, 74, 80, 255));
        dl->AddText(ImVec2(x + 2, barMin.y + 1), IM_COL32(170, 170, 170, 255), std::to_string(f).c_str());
    }

    ImGui::SetCursorScreenPos(barMin);
    ImGui::InvisibleButton("scrub", ImVec2(barW, barH));
    const ImVec2 mouse = ImGui::GetIO().MousePos;
    // A press on a key selects it and starts moving it; elsewhere it scrubs.
    if (ImGui::IsItemActivated()) {
        t.dragged.reset();
        for (int r = 0; trackOfRow(r) && !t.dragged; ++r) {
            const float y = barMin.y + kRulerHeight + (r + 0.5f) * kRowHeight;
            for (const Key& k : trackOfRow(r)->keys)
                if (std::abs(mouse.x - xOf(k.frame)) <= kKeyRadius + 1 && std::abs(mouse.y - y) <= kRowHeight / 2) {
                    t.dragged = KeyRef{trackOfRow(r)->target, k.frame};
                    t.dragFrame = k.frame;
                    break;
                }
        }
        t.selected = t.dragged;
        if (!t.dragged) t.playing = false;
    }
    if (ImGui::IsItemActive()) {
        if (t.dragged)
            t.dragFrame = frameAt(mouse.x);
        else
            t.frame = frameAt(mouse.x);
    }
    if (ImGui::IsItemDeactivated() && t.dragged) {
        if (t.dragFrame != t.dragged->frame && moveKey(a, *t.dragged, t.dragFrame))
            t.selected = KeyRef{t.dragged->target, t.dragFrame};
        t.dragged.reset();
    }

    for (int r = 0; trackOfRow(r); ++r) {
        const Track& track = *trackOfRow(r);
        const float y = barMin.y + kRulerHeight + (r + 0.5f) * kRowHeight;
        for (const Key& k : track.keys) {
            const KeyRef ref{track.target, k.frame};
            const bool moving = t.dragged && *t.dragged == ref;
            const float x = xOf(moving ? t.dragFrame : k.frame);
            const bool selected = t.selected && *t.selected == ref;
            diamond(dl, ImVec2(x, y), kKeyRadius, selected ? kSelectedColor : kKeyColor, true);
        }
    }
    const float px = xOf(t.frame);
    dl->AddLine(ImVec2(px, barMin.y), ImVec2(px, barMax.y), kPlayheadColor, 2.0f);
    if (trackCount > rows) {
        const bool overTracks = ImGui::IsWindowHovered() && mouse.y >= origin.y && mouse.y < barMax.y;
        if (overTracks && ImGui::GetIO().MouseWheel != 0.0f)
            t.firstRow = std::clamp(t.firstRow - int(std::lround(ImGui::GetIO().MouseWheel)), 0, trackCount - rows);
        char shown[96];
        std::snprintf(shown, sizeof shown, "tracks %d-%d of %d (mouse wheel scrolls)", t.firstRow + 1,
                      t.firstRow + rows, trackCount);
        dl->AddText(ImVec2(origin.x, barMax.y), IM_COL32(150, 150, 150, 255), shown);
    }
    ImGui::SetCursorScreenPos(ImVec2(origin.x, barMax.y + 2));
}

}  // namespace

void handleTimelineShortcuts(EditorState& s) {
    s.timeline.keyMarkers.clear();
    if (s.doc.plane || ImGui::GetIO().WantTextInput) return;
    TimelineState& t = s.timeline;
    if ((t.hovered || viewportHasKeyboard(s)) && consume(s, GLFW_KEY_SPACE)) {
        if (t.playing)
            t.playing = false;
        else
            startPlaying(s);
    }
    if (t.hovered && t.selected && consume(s, GLFW_KEY_DELETE)) {
        deleteKey(s.doc.preset.animation, *t.selected);
        t.selected.reset();
    }
}

void drawTimelinePanel(EditorState& s) {
    TimelineState& t = s.timeline;
    t.height = 0.0f;
    t.hovered = false;
    if (s.doc.plane) return;
    Animation& a = s.doc.preset.animation;
    if (t.playing) {
        const PlaybackStep step = playbackFrame(shownAnimation(a), t.playStartFrame, s.now - t.playStartTime, t.loop);
        t.frame = step.frame;
        if (step.ended) t.playing = false;
        glfwPostEmptyEvent();  // the next frame comes now, not when an event wakes the loop
    }
    t.frame = std::clamp(t.frame, a.firstFrame, shownLastFrame(a));
    if (!t.appliedFrame || *t.appliedFrame != t.frame || t.appliedAnimation != a) showFrame(s);

    const int rows = std::max(1, std::min(int(a.tracks.size()), kMaxRowsShown));
    const ImGuiStyle& style = ImGui::GetStyle();
    t.height = style.WindowPadding.y * 2 + ImGui::GetFrameHeightWithSpacing() + kRulerHeight + rows * kRowHeight +
               (int(a.tracks.size()) > kMaxRowsShown ? ImGui::GetTextLineHeight() : 0.0f) + 4;
    Layout& l = s.layout;
    l.viewportH = std::max(l.viewportH - t.height, 16.0f);
    ImGui::SetNextWindowPos(ImVec2(l.viewportX, l.viewportY + l.viewportH));
    ImGui::SetNextWindowSize(ImVec2(l.viewportW, t.height));
    ImGui::Begin("Timeline", nullptr,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                     ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    // The pointer over the panel's rectangle, whatever item is active elsewhere (Space, Delete).
    const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    t.hovered = ImGui::IsMouseHoveringRect(pos, ImVec2(pos.x + size.x, pos.y + size.y), false);
    controlsRow(s);
    scrubBar(s);
    ImGui::End();
}

void keyMarker(EditorState& s, const std::string& target, const std::vector<double>& value) {
    TimelineState& t = s.timeline;
    Animation& a = s.doc.preset.animation;
    const Track* track = findTrack(a, target);
    const Key* key = track ? keyAt(*track, t.frame) : nullptr;
    const bool changed = track && differsFromTrack(s.doc.preset, *track, t.frame, value);
    const float size = ImGui::GetFrameHeight();
    ImGui::PushID(target.c_str());
    const ImVec2 at = ImGui::GetCursorScreenPos();
    const ImVec2 centre(at.x + size * 0.35f, at.y + size / 2);
    if (ImGui::InvisibleButton("key", ImVec2(size * 0.7f, size))) {
        if (key && !changed)
            deleteKey(a, {target, double(t.frame)});
        else
            addKeyHere(s, target, value);
    }
    t.keyMarkers.push_back({target, {centre.x, centre.y}});
    const ImU32 color = changed ? kChangedColor : track ? kKeyColor : kUnkeyedColor;
    diamond(ImGui::GetWindowDrawList(), centre, size * 0.27f, color, key != nullptr);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(!track    ? "Click: add a key at frame %d"
                          : changed ? "Changed from the animation: click to key it at frame %d"
                          : key     ? "Key at frame %d: click to delete it"
                                    : "Animated: click to add a key at frame %d",
                          t.frame);
    if (ImGui::BeginPopupContextItem("key_menu")) {
        if (ImGui::MenuItem(("Add key at frame " + std::to_string(t.frame)).c_str())) addKeyHere(s, target, value);
        if (ImGui::MenuItem(("Delete key at frame " + std::to_string(t.frame)).c_str(), nullptr, false, key))
            deleteKey(a, {target, double(t.frame)});
        interpolationItems(s, target);
        ImGui::EndPopup();
    }
    ImGui::PopID();
    ImGui::SameLine(0, 2);
}

}  // namespace fraktal::editor
