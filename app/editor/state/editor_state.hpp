// Everything the editor knows, in plain structs owned by runEditor() and passed to the panels
// by reference. Nothing lives in function statics, so two editors (or a test) never share state.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/editor/document/autosave.hpp"
#include "app/editor/document/document.hpp"
#include "app/editor/document/export_job.hpp"
#include "app/editor/document/file_browser.hpp"
#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/lights_edits.hpp"
#include "app/editor/document/mesh_export_job.hpp"
#include "app/editor/document/slow_stack.hpp"
#include "app/editor/document/timeline_edits.hpp"
#include "app/editor/document/undo_history.hpp"
#include "app/editor/input/camera_controller.hpp"
#include "app/editor/input/imgui_input.hpp"
#include "app/editor/input/pointer_input.hpp"
#include "app/editor/state/custom_block_editor.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/value_clamp.hpp"
#include "core/color/color_pipeline.hpp"

namespace fraktal::editor {

struct FileState {
    std::filesystem::path path;    // empty for a new, never saved document
    std::string savedFingerprint;  // fingerprint(doc) when last opened or saved
    std::vector<std::string> recent;
    std::filesystem::path recentListFile;  // where `recent` persists (empty: not persisted)
};

struct PanelVisibility {
    bool formula = true;
    bool sidebar = true;     // camera, render, presets
    bool collapsed = false;  // the side column folded away (Ctrl+Backslash): the viewport takes the width
    bool stats = true;
    bool demo = false;      // ImGui's own metrics, for bug reports (no menu offers it: set it in a debugger)
    bool tour = false;      // Help > Tour
    std::string tourText;   // the tour's text, read when first shown
    bool help = false;      // the shortcut list (F1)
    std::string selectTab;  // a Scene tab to bring to front on the next frame ("Render", ...)
};

// Laid out by the panels each frame; the viewport gets what they leave. One column on the left
// holds the Formula panel above the Scene panel, so at 1280x800 the viewport is a landscape
// rectangle of about 70 % of the window. Widths and the split are remembered (panel_ini.cpp).
struct Layout {
    float menuHeight = 0.0f;
    float leftWidth = 360.0f;      // the side column
    float formulaHeight = 500.0f;  // the Formula panel's share of the column, from its top
    float viewportX = 0, viewportY = 0, viewportW = 1, viewportH = 1;  // in window coordinates
    // Widgets as last drawn, by name ("tab:Render", "button:Store 1", "Render mode"): x, y, w, h
    // in window coordinates, for tests that click them (the state file).
    std::map<std::string, std::array<float, 4>> widgetRects;
    std::string sceneTab;    // the Scene panel's tab in front
    bool popupOpen = false;  // a menu or popup is open after the frame (the state file)
};

// The editor window's place on the screen, remembered between runs (panel_ini.cpp); 0 size: unknown.
struct WindowPlacement {
    int x = 0, y = 0, width = 0, height = 0;
    bool hasPosition = false;
};

// What to do once the user answered the unsaved-changes question.
enum class PendingKind { None, New, NewPlane, Open, Quit };
struct PendingAction {
    PendingKind kind = PendingKind::None;
    std::filesystem::path path;  // for Open
};

// The Open / Save As file browser (file_dialogs.cpp).
struct FileBrowser {
    bool saving = false;
    bool shown = false;  // drawn this frame
    std::filesystem::path folder;
    std::string name;  // the path field: a name in `folder`, or a path
    BrowserFilter filter = BrowserFilter::PresetsAndExrs;
    std::vector<BrowserEntry> entries;
    bool listed = false;            // `entries` are those of `folder` under `filter`
    bool focusField = false;        // the path field takes the keys on the next frame
    bool fieldActive = false;       // the path field has the keys (typing goes into it)
    std::string error;              // the folder cannot be read, or the chosen file cannot be opened
    std::filesystem::path replace;  // Save As: the existing file the user is asked about
};

struct Dialogs {
    bool openPath = false;        // opens the file browser to open a file
    bool saveAs = false;          // opens it to save as
    bool unsaved = false;         // "Save changes?" prompt
    bool exportStill = false;     // F12
    bool exportMesh = false;      // File > Export mesh...
    bool environmentMap = false;  // opens the file browser to choose the Lights tab's environment map
    std::string pathInput;        // Save As: the path to start from
    FileBrowser browser;
    PendingAction pending;
};

struct Thumbnail {
    std::filesystem::path file;
    std::string name;
    unsigned texture = 0;  // GL texture, 0 until rendered
    bool failed = false;
};

struct PresetBrowser {
    std::vector<Thumbnail> entries;
    bool scanned = false;
    bool visible = false;    // the tab was drawn this frame: thumbnails render only then
    bool rendering = false;  // shown with thumbnails missing: the next frames render them (the window stays busy)
    std::vector<std::filesystem::path> folders;  // shipped presets/, then the user's folder
};

struct StatusLine {
    std::string text;
    bool error = false;
    double until = 0.0;  // glfwGetTime() at which it fades
};

// An opened frag's #presets, FragM's preset list: the Formula panel offers them, and choosing one
// imports the frag again with it (applyFragPreset). Empty for any other document.
struct FragPresets {
    std::filesystem::path file;
    std::vector<std::string> names;
    std::string applied;  // the preset the document's values came from
};

// Which node of a 2D formula the Formula panel has selected: a start node, a loop node or the
// estimator (index unused).
enum class PlaneList { Start, Loop, Estimator };
struct PlaneSelection {
    PlaneList list = PlaneList::Loop;
    int index = 0;
    bool operator==(const PlaneSelection&) const = default;
};

struct EditorState {
    Document doc;
    // The OCIO config ($OCIO, else the shipped one) the viewport displays through and the Render
    // tab lists displays and views from; empty only when no config can be read.
    std::optional<ColorPipeline> color;
    AutosaveState autosave;
    UndoHistory history;
    FileState file;
    PanelVisibility panels;
    Layout layout;
    WindowPlacement window;
    CameraControls cameraControls;
    CustomBlockEditor customBlockEditor;
    EyeDistance eyeDistance;    // the DE at the eye for the fly speed (GL probe for custom GLSL)
    AutoStepFactor stepFactor;  // the check's step factor, set after structure changes
    SlowStackAdvice slowStack;  // why that factor is small, and the faster estimator
    Dialogs dialogs;
    PresetBrowser browser;
    // The formula panel's "Add fractal" menu: read from the preset folders when the menu opens (a
    // few dozen small files), not every frame.
    std::vector<FractalChoice> fractalChoices;
    ExportJob exportJob;
    MeshExportJob meshExportJob;
    StatusLine status;
    FragPresets fragPresets;
    int selectedNode = 0;           // formula.nodes.size() selects the estimator
    PlaneSelection planeSelection;  // the same for a 2D document
    PlaneViewRect planeHome;        // the 2D view as opened: "reset view" returns to it
    bool cameraGesture = false;     // a drag or fly key is held: do not commit undo mid-gesture
    bool quit = false;
    double now = 0.0;                            // seconds, for status fades and frame time
    std::vector<std::filesystem::path> dropped;  // files dropped on the window this frame
    std::vector<PointerEvent> pointerEvents;     // mouse events since the last frame (GLFW callbacks)
    vec2 cursorAt{0.0};                          // the last cursor position GLFW reported
    ViewportDrag drag;                           // the viewport's drag, from those events
    std::vector<ViewportClick> viewportClicks;   // clicks on the 3D viewport this frame
    FlyKeys flyKeys;                             // fly keys, from key events
    std::vector<KeyPress> keyPresses;            // key presses since the last frame (shortcuts)
    InputQueue input;                            // window events not yet handed to a frame, in order
    TimelineState timeline;                      // the animation's current frame, playback, selection
    ParamWidgetsShown paramWidgets;              // the parameter widgets drawn this frame (state file)
    ClampReports clampReports;                   // values typed outside a slider's range, for the status line
    LightsPanel lights;                          // the Lights tab's selection, typed map path, focus pick
    // `fraktal edit --aa-cap N`: the viewport stops its anti-aliasing at N samples per pixel on this
    // machine, whatever the document's cap (which is saved as it is); 0 for the document's.
    int aaCapLimit = 0;
};

bool isDirty(const EditorState& s);
std::string windowTitle(const EditorState& s);

}  // namespace fraktal::editor
