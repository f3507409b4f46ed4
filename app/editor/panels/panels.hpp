// The editor's panels: one function per panel, each in its own file, drawing from and into the
// EditorState it is given. They hold no state of their own.
#pragma once

#include <filesystem>
#include <string>

#include "app/editor/state/editor_state.hpp"
#include "app/editor/viewport/plane_viewport.hpp"
#include "app/editor/viewport/viewport_view.hpp"

namespace fraktal::editor {

void handleShortcuts(EditorState& s);                          // shortcuts.cpp
void drawMenuBar(EditorState& s);                              // menu_bar.cpp
void drawFormulaPanel(EditorState& s, const ViewportView& v);  // formula_panel.cpp
void beginFormulaWindow(EditorState& s);                       // formula_panel.cpp: the column's top
// The side column (sidebar.cpp): whether its top (Formula) or lower (Scene) panel shows, and
// Begin() of one of them at its place, with the edges that resize the column and the split.
bool sideColumnShows(const PanelVisibility& p, bool top);
void beginSideColumnWindow(EditorState& s, const char* name, bool* open, bool top);
// Ends the current window's content with the blank space that keeps its scroll when the content
// got shorter (scroll_keep.hpp): called last before End() by the panels whose clicks change what
// lies below the pointer.
void keepWindowScroll();
// The 2D document's panels (plane_*.cpp); `compileError` is the 2D view's.
void drawPlaneFormulaPanel(EditorState& s, const std::string& compileError);  // plane_formula_panel.cpp
void drawPlaneViewTab(EditorState& s);                                        // plane_view_tab.cpp
void drawPlaneColouringTab(EditorState& s);                                   // plane_colouring_tab.cpp
void drawPlaneStatsOverlay(EditorState& s, const PlaneViewport& v);           // stats_overlay.cpp
void drawSidebar(EditorState& s);                                             // sidebar.cpp: the tabs below
void drawCameraTab(EditorState& s);                                           // camera_panel.cpp
void drawRenderTab(EditorState& s);                                           // render_panel.cpp
void drawShadingTab(EditorState& s);                                          // shading_panel.cpp
void drawLightsTab(EditorState& s);                                           // lights_panel.cpp
// Takes `file` as the environment map when it is a readable EXR; otherwise the Lights tab says
// why and the document keeps its map.
void chooseEnvironmentMap(EditorState& s, const std::filesystem::path& file);  // lights_panel.cpp
void drawPresetsTab(EditorState& s);                                           // preset_browser.cpp
void drawStatsOverlay(EditorState& s, const ViewportView& v);                  // stats_overlay.cpp
void drawExportDialog(EditorState& s);                                         // export_dialog.cpp
void drawMeshExportDialog(EditorState& s);                                     // mesh_export_dialog.cpp
void drawFileDialogs(EditorState& s);                                          // file_dialogs.cpp
void drawStatusLine(EditorState& s);                                           // stats_overlay.cpp
void drawRecoveryDialog(EditorState& s);                                       // recovery_dialog.cpp
void drawCustomBlockEditor(EditorState& s, const std::string& compileError);   // custom_block_panel.cpp

void drawShortcutHelp(EditorState& s);  // help_window.cpp

void applyEditorStyle(float scale);  // style.cpp
// Records the last item's rectangle under `name` in layout.widgetRects (sidebar.cpp).
void noteWidgetRect(Layout& layout, const std::string& name);

}  // namespace fraktal::editor
