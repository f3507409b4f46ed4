// The editor's main loop: GLFW window and GL 4.5 context, Dear ImGui panels, the viewport
// behind them, undo commits between gestures, autosave, and the --frames/--screenshot path for
// tests.
#include "app/editor/editor.hpp"

#include <epoxy/gl.h>
// epoxy first: GLFW must not pull in the system GL header.
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>
#include <imgui_internal.h>  // MarkIniSettingsDirty

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <thread>

#include "app/editor/document/preset_files.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/state/panel_ini.hpp"
#include "app/editor/state_dump.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/viewport/background_compiler.hpp"
#include "app/editor/viewport/camera_input.hpp"
#include "app/editor/viewport/export_frame.hpp"
#include "app/editor/viewport/frame_log.hpp"
#include "app/editor/viewport/screenshot.hpp"
#include "app/editor/viewport/thumbnails.hpp"
#include "app/editor/viewport/ui_layer_cache.hpp"
#include "app/editor/viewport/ui_redraw.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "core/atomic_file.hpp"

namespace fraktal::editor {

namespace fs = std::filesystem;

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

namespace {

constexpr int kDefaultWidth = 1280, kDefaultHeight = 800;

constexpr const char* kNoDisplay =
    "fraktal: no display: the editor needs an X11 or Wayland session ($DISPLAY is not set).\n"
    "  For headless use, render a still:   fraktal render PRESET -o OUT.exr\n"
    "  Or run the editor under Xvfb:        xvfb-run -a fraktal edit PRESET\n";

EditorState* stateOf(GLFWwindow* w) { return static_cast<EditorState*>(glfwGetWindowUserPointer(w)); }

void onDrop(GLFWwindow* w, int count, const char** paths) {
    for (int i = 0; i < count; ++i) stateOf(w)->dropped.emplace_back(paths[i]);
}

// Tests: the paths listed in `file` (one a line), once it appears, go through the drop callback as
// a drop of those files on the window does (X test tools cannot drag files); the file is removed.
void replayDrops(GLFWwindow* w, const fs::path& file) {
    std::ifstream in(file);
    if (!in) return;
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    in.close();
    std::error_code ec;
    fs::remove(file, ec);
    std::vector<const char*> paths;
    for (const std::string& l : lines) paths.push_back(l.c_str());
    if (!paths.empty()) onDrop(w, int(paths.size()), paths.data());
}

// Closing the window with unsaved changes asks first (the prompt's answer quits).
void onClose(GLFWwindow* w) {
    EditorState& s = *stateOf(w);
    if (!isDirty(s)) return;
    glfwSetWindowShouldClose(w, GLFW_FALSE);
    requestAction(s, {PendingKind::Quit, {}});
}

// Mouse and key events go to the input queue (imgui_input.hpp) with the cursor position they
// happened at; each frame hands its share to ImGui and to the editor's own handlers. ImGui's
// backend, installed after these, calls them before its own handlers.
void onCursorPos(GLFWwindow* w, double x, double y) {
    stateOf(w)->input.push({InputEvent::Kind::CursorMove, x, y});
    stateOf(w)->cursorAt = vec2(x, y);
}

// GLFW's X11 glfwGetCursorPos asks the server where the pointer is now, which can be past the
// press still waiting in the queue: a press takes the position of the last motion event before it.
void onMouseButton(GLFWwindow* w, int button, int action, int mods) {
    const vec2& at = stateOf(w)->cursorAt;
    stateOf(w)->input.push({InputEvent::Kind::MouseButton, at.x, at.y, button, action == GLFW_PRESS, mods});
}

// Installed over the ImGui backend's own character callback, which would hand the character to
// ImGui at once, ahead of the keys queued before it.
void onChar(GLFWwindow* w, unsigned codepoint) {
    stateOf(w)->input.push({InputEvent::Kind::Char, 0.0, 0.0, int(codepoint), true});
}

// This frame's share of the queued events (imgui_input.hpp): ImGui's io, over what the backend's
// poll set, and the editor's pointer events and key presses.
void takeFrameInput(GLFWwindow* window, EditorState& s) {
    InputQueue& queue = s.input;
    ImGuiIO& io = ImGui::GetIO();
    queue.takeFrame();
    s.pointerEvents = queue.pointerEvents();
    s.keyPresses = queue.keyPresses();
    // Unfocused, the backend says the mouse is nowhere; keep that.
    if (queue.hasCursor() && glfwGetWindowAttrib(window, GLFW_FOCUSED))
        io.MousePos = ImVec2(float(queue.cursorX()), float(queue.cursorY()));
    for (int b = 0; b < InputQueue::kMouseButtons; ++b) io.MouseDown[b] = queue.mouseDown(b);
    for (int k = 0; k < InputQueue::kKeys; ++k) io.KeysDown[k] = queue.keyDown(k);
    io.KeyCtrl = queue.keyDown(GLFW_KEY_LEFT_CONTROL) || queue.keyDown(GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = queue.keyDown(GLFW_KEY_LEFT_SHIFT) || queue.keyDown(GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = queue.keyDown(GLFW_KEY_LEFT_ALT) || queue.keyDown(GLFW_KEY_RIGHT_ALT);
    io.KeySuper = queue.keyDown(GLFW_KEY_LEFT_SUPER) || queue.keyDown(GLFW_KEY_RIGHT_SUPER);
    for (const unsigned c : queue.chars()) io.AddInputCharacter(c);
}

void onKey(GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
    if (action == GLFW_REPEAT) return;
    stateOf(w)->input.push({InputEvent::Kind::Key, 0.0, 0.0, key, action == GLFW_PRESS, mods});
    FlyKey fly = kFlyKeys;
    switch (key) {
        case GLFW_KEY_D: fly = FlyRight; break;
        case GLFW_KEY_A: fly = FlyLeft; break;
        case GLFW_KEY_E: fly = FlyUp; break;
        case GLFW_KEY_Q: fly = FlyDown; break;
        case GLFW_KEY_W: fly = FlyForward; break;
        case GLFW_KEY_S: fly = FlyBack; break;
        default: return;
    }
    // Ctrl+S, Ctrl+D, ... are commands, not moves (a release always ends a move).
    const bool press = action == GLFW_PRESS;
    if (press && (mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER))) return;
    flyKeyEvent(stateOf(w)->flyKeys, fly, press, glfwGetTime());
}

// The window's size and place, for the ini file (saved when ImGui next writes it, and at exit).
void onWindowPos(GLFWwindow* w, int x, int y) {
    WindowPlacement& p = stateOf(w)->window;
    if (p.hasPosition && p.x == x && p.y == y) return;
    p.x = x, p.y = y, p.hasPosition = true;
    ImGui::MarkIniSettingsDirty();
}

void onWindowSize(GLFWwindow* w, int width, int height) {
    WindowPlacement& p = stateOf(w)->window;
    if (width <= 0 || height <= 0 || (p.width == width && p.height == height)) return;  // minimised: keep
    p.width = width, p.height = height;
    ImGui::MarkIniSettingsDirty();
}

// Back to the remembered place when it is still on a monitor's work area (screens change);
// then `placement` holds where the window really is.
void placeWindow(GLFWwindow* window, WindowPlacement& placement) {
    if (placement.hasPosition) {
        int count = 0;
        GLFWmonitor** monitors = glfwGetMonitors(&count);
        for (int i = 0; i < count; ++i) {
            int x = 0, y = 0, w = 0, h = 0;
            glfwGetMonitorWorkarea(monitors[i], &x, &y, &w, &h);
            if (placement.x >= x && placement.y >= y && placement.x < x + w - 32 && placement.y < y + h - 32) {
                glfwSetWindowPos(window, placement.x, placement.y);
                break;
            }
        }
    }
    glfwGetWindowPos(window, &placement.x, &placement.y);
    glfwGetWindowSize(window, &placement.width, &placement.height);
    placement.hasPosition = true;
}

void onGlfwError(int code, const char* text) { std::fprintf(stderr, "fraktal: GLFW error %d: %s\n", code, text); }

// The part of the window the panels leave to the viewport.
void layoutViewport(EditorState& s, float windowW, float windowH) {
    Layout& l = s.layout;
    const bool column = sideColumnShows(s.panels, true) || sideColumnShows(s.panels, false);
    const float left = column ? l.leftWidth : 0.0f;
    l.viewportX = left;
    l.viewportY = l.menuHeight;
    l.viewportW = std::max(windowW - left, 16.0f);
    l.viewportH =
        std::max(windowH - l.menuHeight, 16.0f);  // the timeline takes its height from this (timeline_panel.cpp)
}

// The display texture's rows are top first, as ImGui's image coordinates are.
void drawViewportImage(const EditorState& s, GLuint displayTexture) {
    const Layout& l = s.layout;
    ImDrawList* bg = ImGui::GetBackgroundDrawList();
    const ImVec2 a(l.viewportX, l.viewportY), b(l.viewportX + l.viewportW, l.viewportY + l.viewportH);
    if (displayTexture)
        bg->AddImage(reinterpret_cast<ImTextureID>(static_cast<intptr_t>(displayTexture)), a, b, ImVec2(0, 0),
                     ImVec2(1, 1));
}

// The export frame of the export dialog's size in the viewport (export_frame.hpp).
ExportFrame exportFrameOf(const EditorState& s) {
    const ExportOptions& o = s.exportJob.options;
    const double viewAspect = double(s.layout.viewportW) / std::max(double(s.layout.viewportH), 1.0);
    // "Viewport size" exports the viewport's own pixels (export_dialog.cpp).
    const double exportAspect = kExportSizes[o.sizeIndex].width == 0
                                    ? double(int(s.layout.viewportW)) / std::max(int(s.layout.viewportH), 1)
                                    : double(o.width) / std::max(o.height, 1);
    return exportFrameInView(viewAspect, exportAspect, s.doc.preset.camera.fovY);
}

// The guide: what lies outside the export frame is dimmed, the frame outlined.
void drawExportGuide(const EditorState& s, const ExportFrame& f) {
    if (f.wholeView()) return;
    const Layout& l = s.layout;
    ImDrawList* bg = ImGui::GetBackgroundDrawList();
    const ImVec2 a(l.viewportX, l.viewportY), b(l.viewportX + l.viewportW, l.viewportY + l.viewportH);
    const ImVec2 g0(l.viewportX + float(f.left) * l.viewportW, l.viewportY + float(f.top) * l.viewportH);
    const ImVec2 g1(l.viewportX + float(f.right) * l.viewportW, l.viewportY + float(f.bottom) * l.viewportH);
    const ImU32 dim = IM_COL32(0, 0, 0, 140);
    bg->AddRectFilled(a, ImVec2(b.x, g0.y), dim);
    bg->AddRectFilled(ImVec2(a.x, g1.y), b, dim);
    bg->AddRectFilled(ImVec2(a.x, g0.y), ImVec2(g0.x, g1.y), dim);
    bg->AddRectFilled(ImVec2(g1.x, g0.y), ImVec2(b.x, g1.y), dim);
    bg->AddRect(ImVec2(g0.x - 1, g0.y - 1), ImVec2(g1.x + 1, g1.y + 1), IM_COL32(255, 255, 255, 110));
}

// The viewport of the current document: the 3D one, or the 2D view for a 2D document. Returns
// the compile error to report (empty when none).
// `structure`: the document formula's structureKey(), computed once this frame.
const std::string& drawDocumentViewport(EditorState& s, ViewportView& viewport, PlaneViewport& plane,
                                        const std::string& structure) {
    const Layout& l = s.layout;
    const ImGuiIO& io = ImGui::GetIO();
    const double scale = s.doc.view.renderScale * io.DisplayFramebufferScale.x;
    const int width = int(l.viewportW * scale), height = int(l.viewportH * scale);
    if (s.doc.plane) {
        updatePlaneView(s, std::max(width, 2), std::max(height, 2));
        plane.render(*s.doc.plane, width, height);
        drawViewportImage(s, plane.displayTexture());
        drawPlaneStatsOverlay(s, plane);
        return plane.compileError();
    }
    updateCamera(s);
    viewport.setPresetFile(s.file.path.string());
    const ExportFrame frame = exportFrameOf(s);
    ViewSettings view = s.doc.view;
    if (s.aaCapLimit > 0) view.aaCap = std::min(view.aaCap, s.aaCapLimit);
    // The frame's one revision of the scene: every part of the viewport decides on it. A new
    // structure whose step factor is still measured keeps the last image (the previous factor
    // could overshoot on it) while its programs compile.
    if (s.stepFactor.measuring()) {
        viewport.prepare(s.doc.preset.formula, structure);
    } else if (frame.viewFovY == s.doc.preset.camera.fovY) {
        viewport.render(s.doc.preset, scene::sceneRevision(s.doc.preset, structure), view, width, height);
    } else {  // a wider export: the viewport widens its view to hold the whole export frame
        Preset shown = s.doc.preset;
        shown.camera.fovY = frame.viewFovY;
        viewport.render(shown, scene::sceneRevision(shown, structure), view, width, height);
    }
    drawViewportImage(s, viewport.displayTexture());
    drawExportGuide(s, frame);
    drawStatsOverlay(s, viewport);
    return viewport.compileError();
}

// $OCIO when set, else the shipped config; a broken $OCIO falls back to the shipped one (said in
// the status line) so the editor still opens.
bool loadColorPipeline(EditorState& s) {
    try {
        s.color = ColorPipeline::fromEnvironment();
        return true;
    } catch (const std::exception& e) {
        setStatus(s, std::string(e.what()) + "; using the shipped config", true);
    }
    try {
        s.color = ColorPipeline::fromFile(shippedOcioConfigPath());
        return true;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fraktal: %s\n", e.what());
        return false;
    }
}

}  // namespace

int runEditor(const EditorOptions& o) {
    if (!displayAvailable()) {
        std::fputs(kNoDisplay, stderr);
        return 3;
    }
    glfwSetErrorCallback(onGlfwError);
    if (!glfwInit()) {
        std::fputs(kNoDisplay, stderr);
        return 3;
    }
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);

    EditorState s;
    const fs::path config = configFolder();
    std::error_code ec;
    fs::create_directories(config, ec);
    // The ini is read before the window exists: it holds the window's size and place.
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    const std::string iniFile = (config / "editor.ini").string();
    io.IniFilename = nullptr;
    registerPanelIniHandler(s);
    if (o.useIniFile) {
        ImGui::LoadIniSettingsFromDisk(iniFile.c_str());
        io.IniFilename = iniFile.c_str();
    }
    // An explicit --width/--height wins over the remembered size.
    const int width = o.width > 0 ? o.width : s.window.width > 0 ? s.window.width : kDefaultWidth;
    const int height = o.height > 0 ? o.height : s.window.height > 0 ? s.window.height : kDefaultHeight;
    GLFWwindow* window = glfwCreateWindow(width, height, "fraktal", nullptr, nullptr);
    if (!window) {
        std::fputs(
            "fraktal: cannot create an OpenGL 4.5 core window on this display.\n"
            "  For headless use: fraktal render PRESET -o OUT.exr\n",
            stderr);
        ImGui::DestroyContext();
        glfwTerminate();
        return 3;
    }
    placeWindow(window, s.window);
    glfwMakeContextCurrent(window);
    glfwSwapInterval(o.frames > 0 ? 0 : 1);

    glfwSetWindowUserPointer(window, &s);
    glfwSetWindowPosCallback(window, onWindowPos);
    glfwSetWindowSizeCallback(window, onWindowSize);
    glfwSetDropCallback(window, onDrop);
    glfwSetWindowCloseCallback(window, onClose);
    glfwGetCursorPos(window, &s.cursorAt.x, &s.cursorAt.y);
    glfwSetCursorPosCallback(window, onCursorPos);
    glfwSetMouseButtonCallback(window, onMouseButton);
    glfwSetKeyCallback(window, onKey);

    s.file.recentListFile = config / "recent.json";
    s.file.recent = loadRecentList(s.file.recentListFile);
    s.browser.folders = {fs::path(FRAKTAL_SOURCE_DIR) / "presets", fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "2d",
                         userPresetFolder()};
    fs::create_directories(userPresetFolder(), ec);

    float xscale = 1.0f, yscale = 1.0f;
    glfwGetWindowContentScale(window, &xscale, &yscale);
    applyEditorStyle(xscale);
    io.FontGlobalScale = xscale;
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    glfwSetCharCallback(window, onChar);
    ImGui_ImplOpenGL3_Init("#version 450 core");

    int status = 0;
    if (!loadColorPipeline(s)) status = 2;
    if (status == 0) {
        // Structure edits compile on a worker thread with a hidden context that shares the
        // window's objects; without one (it could not be created) they compile in the frame.
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        GLFWwindow* compileContext = glfwCreateWindow(1, 1, "fraktal compiler", nullptr, window);
        std::unique_ptr<BackgroundCompiler> compiler;
        if (compileContext)
            compiler = std::make_unique<BackgroundCompiler>(
                [compileContext] { glfwMakeContextCurrent(compileContext); }, [] { glfwMakeContextCurrent(nullptr); });
        std::unique_ptr<ViewportView> viewport = makeViewportView(*s.color, compiler.get());
        // A scripted run (--frames, a screenshot at the end) draws the same frames on every
        // machine: each refines the whole view, not a slice fitted to this machine's frame time.
        viewport->setSlicedAtRest(o.frames == 0);
        PlaneViewport planeViewport(*s.color);
        ThumbnailRenderer thumbnails;
        // The thumbnails' programs compile on a worker of their own, with a hidden context of its
        // own, made when the browser first shows (most sessions never open it).
        GLFWwindow* thumbnailContext = nullptr;
        bool thumbnailContextMade = false;
        UiRedrawState uiRedraw;
        UiLayerCache uiLayers;
        newDocument(s);
        if (!o.preset.empty() && !openDocument(s, o.preset)) {
            std::fprintf(stderr, "fraktal: %s\n", s.status.text.c_str());
            if (o.frames > 0) status = 2;  // a scripted run must not pass with the wrong scene
        }
        s.panels.selectTab = o.sidebarTab;
        s.aaCapLimit = o.aaCapLimit;
        if (o.exportWidth > 0 && o.exportHeight > 0) {
            s.exportJob.options.sizeIndex = int(std::size(kExportSizes)) - 1;  // Custom
            s.exportJob.options.width = std::clamp(o.exportWidth, 16, 65536);
            s.exportJob.options.height = std::clamp(o.exportHeight, 16, 65536);
        }
        if (o.sessionRecovery && !beginSession(s.autosave, config, glfwGetTime())) setStatus(s, s.autosave.error, true);
        std::string title, lastState;
        int frame = 0, framesDrawn = 0;
        FrameLog frameLog;
        if (!o.frameLog.empty()) try {
                openFrameLog(frameLog, o.frameLog);
            } catch (const std::exception& e) {
                std::fprintf(stderr, "fraktal: error: %s\n", e.what());
                status = 2;
                s.quit = true;
            }
        // The hooks after the last frame's log line (undo commit, autosave, title): counted into
        // the next frame's phases, whose frame time they are part of.
        double hooksMs = 0.0;
        while (!s.quit && !glfwWindowShouldClose(window)) {
            FramePhases phases;
            const double frameStart = glfwGetTime();
            // Idle when the image is converged and nothing happens: no busy loop on a laptop.
            const bool settled = s.doc.plane ? !planeViewport.refining() : viewport->stats().settled;
            const bool compiling = !s.doc.plane && viewport->stats().compiling;
            const bool busy = o.frames > 0 || !settled || compiling || exportActive(s.exportJob) ||
                              exportActive(s.meshExportJob) || s.browser.rendering || ImGui::IsAnyMouseDown() ||
                              s.input.pending();
            if (busy)
                glfwPollEvents();
            else
                glfwWaitEventsTimeout(0.25);
            s.now = glfwGetTime();
            if (!o.dropReplay.empty()) replayDrops(window, o.dropReplay);
            if (!s.dropped.empty()) {
                openDropped(s, s.dropped.front());
                s.dropped.clear();
            }
            s.browser.visible = false;
            const double eventsEnd = glfwGetTime();
            phases.eventsMs = (eventsEnd - frameStart) * 1000.0;

            ImGui_ImplOpenGL3_NewFrame();
            ImGui_ImplGlfw_NewFrame();
            takeFrameInput(window, s);
            ImGui::NewFrame();
            s.paramWidgets.clear();
            std::optional<ReportClamps> reportClamps(std::in_place, s.clampReports);
            handleTimelineShortcuts(s);
            handleShortcuts(s);
            drawMenuBar(s);
            if (s.doc.plane)
                drawPlaneFormulaPanel(s, planeViewport.compileError());
            else
                drawFormulaPanel(s, *viewport);
            drawSidebar(s);
            // The formula's structure as the panels left it, computed once for the frame: nothing
            // later in the frame edits the node list (the timeline keys values, the viewport moves
            // the camera; the custom-block editor and the dialogs draw after the viewport), so the
            // step factor and the viewport's scene revision share it.
            const std::string structure = s.doc.plane ? std::string() : s.doc.preset.formula.structureKey();
            // The step factor measured for a new structure joins the edit's undo step.
            updateDerivedValues(s, structure);
            if (!s.doc.plane) s.slowStack.update(s.doc.preset.formula, s.doc.preset.camera, s.stepFactor);
            layoutViewport(s, io.DisplaySize.x, io.DisplaySize.y);
            drawTimelinePanel(s);
            const std::string compileError = drawDocumentViewport(s, *viewport, planeViewport, structure);
            drawCameraPathOverlay(s);
            drawStatusLine(s);
            drawExportDialog(s);
            drawMeshExportDialog(s);
            drawCustomBlockEditor(s, compileError);
            drawFileDialogs(s);
            drawRecoveryDialog(s);
            drawShortcutHelp(s);
            if (s.panels.demo) ImGui::ShowMetricsWindow(&s.panels.demo);
            s.layout.popupOpen = ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel);
            if (s.browser.visible && !thumbnailContextMade) {
                thumbnailContextMade = true;
                glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
                thumbnailContext = glfwCreateWindow(1, 1, "fraktal thumbnails", nullptr, window);
                if (thumbnailContext)
                    thumbnails.compiler = std::make_unique<BackgroundCompiler>(
                        [thumbnailContext] { glfwMakeContextCurrent(thumbnailContext); },
                        [] { glfwMakeContextCurrent(nullptr); }, viewport::WarmUpFrames::Still);
            }
            s.browser.rendering = s.browser.visible && renderNextThumbnail(thumbnails, s.browser, *s.color);
            reportClamps.reset();
            // A typed value the slider brought into its range: said on the next frame's status line.
            if (const std::optional<ClampNotice> clamped = s.clampReports.take())
                setStatus(s, clampMessage(*clamped), true);

            ImGui::Render();
            const double panelsEnd = glfwGetTime();
            phases.panelsMs = (panelsEnd - eventsEnd) * 1000.0;
            int fbW = 0, fbH = 0;
            glfwGetFramebufferSize(window, &fbW, &fbH);
            glBindFramebuffer(GL_FRAMEBUFFER, 0);
            glViewport(0, 0, fbW, fbH);
            // The window's background. No full-window rectangle in ImGui's draw lists on top of
            // this: on a software rasteriser a blended layer of the whole window costs about a
            // third of the UI's drawing time (bench/README.md, "The editor under a person's hands").
            // During a camera gesture most frames copy the last whole window back and draw only
            // the live layers over it (viewport/ui_redraw.hpp).
            const UiDraw uiDraw = planUiDraw(uiRedraw, s.cameraGesture, fbW, fbH, o.uiCache && o.frames == 0);
            // The viewport's rectangle in framebuffer pixels: every frame draws it whole.
            const float toPixels = io.DisplaySize.x > 0.0f ? float(fbW) / io.DisplaySize.x : 1.0f;
            const UiLayerCache::Rect viewportPixels{
                int(s.layout.viewportX * toPixels), int(s.layout.viewportY * toPixels),
                int(s.layout.viewportW * toPixels), int(s.layout.viewportH * toPixels)};
            if (uiDraw == UiDraw::Cached) {
                uiLayers.restore(fbW, fbH, viewportPixels);
                ImGui_ImplOpenGL3_RenderDrawData(uiLayers.liveLayers(*ImGui::GetDrawData()));
            } else {
                glClearColor(12 / 255.0f, 13 / 255.0f, 15 / 255.0f, 1.0f);
                glClear(GL_COLOR_BUFFER_BIT);
                ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
                if (uiDraw == UiDraw::FullAndCapture) uiLayers.capture(fbW, fbH, viewportPixels);
            }

            const double drawEnd = glfwGetTime();
            phases.drawMs = (drawEnd - panelsEnd) * 1000.0;
            // Settled: the image on screen is this document's final one. Further rounds of the step
            // factor's measurement may still change the factor, and the image with it.
            const bool viewSettled =
                s.doc.plane ? !planeViewport.refining() : viewport->stats().settled && !s.stepFactor.refining();
            const auto logThisFrame = [&] {
                const float viewportRect[4] = {s.layout.viewportX, s.layout.viewportY, s.layout.viewportW,
                                               s.layout.viewportH};
                if (!s.doc.plane)
                    logFrame(frameLog, glfwGetTime(), viewport->stats(), s.doc.preset.camera, viewportRect, uiDraw,
                             s.browser.rendering, phases);
            };
            // A scripted run counts frames the viewport drew, not frames spent waiting for a compile.
            if (o.frames > 0 && !(!s.doc.plane && viewport->stats().compiling) &&
                (++frame >= o.frames || (o.untilSettled && viewSettled))) {
                if (!o.screenshot.empty()) {
                    try {
                        saveWindowScreenshot(o.screenshot, fbW, fbH);
                        std::printf("fraktal: wrote %s (%d x %d, %d frames)\n", o.screenshot.c_str(), fbW, fbH, frame);
                    } catch (const std::exception& e) {
                        std::fprintf(stderr, "fraktal: error: %s\n", e.what());
                        status = 2;
                    }
                }
                if (!compileError.empty()) {
                    std::fprintf(stderr, "fraktal: %s\n", compileError.c_str());
                    status = 2;
                }
                logThisFrame();  // the frame the run ends on (what the screenshot shows)
                break;
            }
            glfwSwapBuffers(window);
            const double swapEnd = glfwGetTime();
            phases.swapMs = (swapEnd - drawEnd) * 1000.0;
            ++framesDrawn;
            if (!o.stateFile.empty()) {
                try {
                    writeStateFile(o.stateFile,
                                   stateJson(s, framesDrawn, compileError, viewSettled,
                                             s.doc.plane ? nullptr : &viewport->stats(), uiDraw),
                                   lastState);
                    replaceFileForReaders(frameTickFile(o.stateFile),
                                          frameTickLine(framesDrawn, s.input.pendingCount(), viewSettled));
                } catch (const std::exception& e) {
                    std::fprintf(stderr, "fraktal: %s\n", e.what());
                }
            }
            if (o.slowFrameMs > 0) std::this_thread::sleep_for(std::chrono::milliseconds(o.slowFrameMs));
            phases.afterMs = hooksMs + (glfwGetTime() - swapEnd) * 1000.0;
            logThisFrame();
            const double hooksStart = glfwGetTime();

            // One undo step per finished gesture: commit only when nothing is being dragged.
            if (!ImGui::IsAnyItemActive() && !s.cameraGesture) s.history.commit(s.doc);
            autosaveTick(s.autosave, s.doc, s.file.path, isDirty(s), s.now);
            if (!s.autosave.error.empty()) {
                setStatus(s, s.autosave.error, true);
                s.autosave.error.clear();
            }
            if (const std::string t = windowTitle(s); t != title) {
                title = t;
                glfwSetWindowTitle(window, title.c_str());
            }
            hooksMs = (glfwGetTime() - hooksStart) * 1000.0;
        }
        closeFrameLog(frameLog);
        finishExport(s.exportJob);
        finishExport(s.meshExportJob);
        releaseThumbnails(s.browser);
        thumbnails.viewport.reset();
        thumbnails.compiler.reset();  // joins its worker, which releases the hidden context
        if (thumbnailContext) glfwDestroyWindow(thumbnailContext);
        endSession(s.autosave);
        viewport.reset();
        s.eyeDistance.release();
        compiler.reset();  // joins the worker, which releases the hidden context
        if (compileContext) glfwDestroyWindow(compileContext);
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return status;
}

}  // namespace fraktal::editor
