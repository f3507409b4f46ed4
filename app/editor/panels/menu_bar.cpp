// The main menu, with every shortcut shown next to its command (shortcuts.cpp handles them).
#include <imgui.h>

#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/viewport/camera_input.hpp"
#include "core/scene/formula_fit.hpp"

namespace fraktal::editor {

void drawMenuBar(EditorState& s) {
    if (!ImGui::BeginMainMenuBar()) return;
    const bool fileOpen = ImGui::BeginMenu("File");
    if (!fileOpen) noteWidgetRect(s.layout, "menu:File");  // the menu's title, where a click opens it
    if (fileOpen) {
        if (ImGui::MenuItem("New 3D", "Ctrl+N")) requestAction(s, {PendingKind::New, {}});
        if (ImGui::MenuItem("New 2D", "Ctrl+Shift+N")) requestAction(s, {PendingKind::NewPlane, {}});
        if (ImGui::MenuItem("Open...", "Ctrl+O")) s.dialogs.openPath = true;
        if (ImGui::BeginMenu("Open recent", !s.file.recent.empty())) {
            for (const std::string& r : s.file.recent)
                if (ImGui::MenuItem(r.c_str())) requestAction(s, {PendingKind::Open, r});
            ImGui::EndMenu();
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Save", "Ctrl+S")) saveDocument(s);
        if (ImGui::MenuItem("Save as...", "Ctrl+Shift+S")) {
            s.dialogs.pathInput = s.file.path.string();
            s.dialogs.saveAs = true;
        }
        ImGui::Separator();
        if (ImGui::MenuItem("Export still...", "F12")) s.dialogs.exportStill = true;
        // A 2D document is a plane: there is no surface to print.
        const bool plane = s.doc.plane.has_value();
        if (ImGui::MenuItem("Export mesh...", nullptr, false, !plane)) s.dialogs.exportMesh = true;
        if (plane && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
            ImGui::SetTooltip("A 2D document has no surface to mesh: meshes are made of 3D documents.");
        noteWidgetRect(s.layout, "menu:File/Export mesh...");
        ImGui::Separator();
        if (ImGui::MenuItem("Quit", "Ctrl+Q")) requestAction(s, {PendingKind::Quit, {}});
        ImGui::EndMenu();
    }
    const bool editOpen = ImGui::BeginMenu("Edit");
    if (!editOpen) noteWidgetRect(s.layout, "menu:Edit");  // the menu's title, where a click opens it
    if (editOpen) {
        // Says what it will do: "Undo change of scale", "Redo add Box fold". The items are noted
        // by their text (the state file's widgets: what the menu reads, for the Xvfb tests).
        s.history.commit(s.doc);
        const std::string undoText = "Undo " + s.history.undoLabel(), redoText = "Redo " + s.history.redoLabel();
        std::erase_if(s.layout.widgetRects, [](const auto& w) {
            return w.first.starts_with("menu:Undo") || w.first.starts_with("menu:Redo");
        });
        if (ImGui::MenuItem(undoText.c_str(), "Ctrl+Z", false, s.history.canUndo())) undo(s);
        noteWidgetRect(s.layout, "menu:" + undoText);
        if (ImGui::MenuItem(redoText.c_str(), "Ctrl+Shift+Z", false, s.history.canRedo())) redo(s);
        noteWidgetRect(s.layout, "menu:" + redoText);
        ImGui::EndMenu();
    }
    const bool viewOpen = ImGui::BeginMenu("View");
    if (!viewOpen) noteWidgetRect(s.layout, "menu:View");
    if (viewOpen) {
        // The items are noted by their text, as the Edit menu's: what the menu offers, for the tests.
        std::erase_if(s.layout.widgetRects, [](const auto& w) { return w.first.starts_with("menu:View/"); });
        if (ImGui::MenuItem("Formula panel", "F2", &s.panels.formula) && s.panels.formula) s.panels.collapsed = false;
        noteWidgetRect(s.layout, "menu:View/Formula panel");
        if (ImGui::MenuItem("Scene panel", "F3", &s.panels.sidebar) && s.panels.sidebar) s.panels.collapsed = false;
        noteWidgetRect(s.layout, "menu:View/Scene panel");
        bool column = !s.panels.collapsed;
        if (ImGui::MenuItem("Side panels", "Ctrl+\\", &column)) s.panels.collapsed = !column;
        noteWidgetRect(s.layout, "menu:View/Side panels");
        ImGui::MenuItem("Stats overlay", "F4", &s.panels.stats);
        noteWidgetRect(s.layout, "menu:View/Stats overlay");
        ImGui::Separator();
        bool fly = s.cameraControls.mode == CameraMode::Fly;
        if (ImGui::MenuItem("Fly camera", "V", &fly, !s.doc.plane))
            s.cameraControls.mode = fly ? CameraMode::Fly : CameraMode::Orbit;
        if (ImGui::MenuItem("Frame object", "F", false, !s.doc.plane)) frameObject(s);
        ImGui::MenuItem("Camera path", nullptr, &s.timeline.showCameraPath, !s.doc.plane);
        if (ImGui::MenuItem("Reset view", "Home")) {
            if (s.doc.plane)
                resetPlaneView(s);
            else
                s.doc.preset.camera = defaultViewFor(s.doc.preset.formula, s.doc.preset.camera);
        }
        ImGui::EndMenu();
    }
    const bool helpOpen = ImGui::BeginMenu("Help");
    if (!helpOpen) noteWidgetRect(s.layout, "menu:Help");
    if (helpOpen) {
        if (ImGui::MenuItem("Tour", nullptr, &s.panels.tour)) ImGui::SetWindowFocus("Tour");
        noteWidgetRect(s.layout, "menu:Help/Tour");
        ImGui::MenuItem("Shortcuts", "F1", &s.panels.help);
        noteWidgetRect(s.layout, "menu:Help/Shortcuts");
        ImGui::EndMenu();
    }
    // Folds the side column away and back (Ctrl+Backslash): the arrow points where it goes.
    if (ImGui::ArrowButton("##side_column", s.panels.collapsed ? ImGuiDir_Right : ImGuiDir_Left))
        s.panels.collapsed = !s.panels.collapsed;
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(s.panels.collapsed ? "Show the side panels (Ctrl+\\)" : "Hide the side panels (Ctrl+\\)");
    // The document's name and unsaved mark, right-aligned.
    const std::string title =
        (isDirty(s) ? "* " : "") + (s.file.path.empty() ? std::string("untitled") : s.file.path.filename().string());
    ImGui::SameLine(ImGui::GetWindowWidth() - ImGui::CalcTextSize(title.c_str()).x - 16);
    ImGui::TextDisabled("%s", title.c_str());
    s.layout.menuHeight = ImGui::GetWindowHeight();
    ImGui::EndMainMenuBar();
}

}  // namespace fraktal::editor
