#include "app/editor/state_dump.hpp"

#include <nlohmann/json.hpp>

#include "app/editor/widgets/node_list_widgets.hpp"
#include "app/editor/widgets/text_fit.hpp"
#include "core/atomic_file.hpp"

namespace fraktal::editor {

using nlohmann::json;

namespace {

// The scene's lighting as the Lights tab shows it, and where its widgets were drawn.
json lightsJson(const Lighting& l, const LightsPanel& p) {
    json lights = json::array();
    for (const Light& light : l.lights)
        lights.push_back({{"type", lightTypeNames(light.type).label},
                          {"enabled", light.enabled},
                          {"intensity", light.intensity},
                          {"size", light.size},
                          {"height", light.height}});
    json widgets = json::object();
    for (const auto& [name, r] : p.widgets) widgets[name] = {r[0], r[1], r[2], r[3]};
    return {{"count", l.lights.size()},
            {"items", lights},
            {"selected", p.selected},
            {"environmentMap", l.environment.map},
            {"aperture", l.lens.apertureRadius},
            {"focusDistance", l.lens.focusDistance},
            {"blades", l.lens.blades},
            {"pickFocus", p.pickFocus},
            {"message", p.message},
            {"messageIsError", p.messageIsError},
            {"widgets", widgets}};
}

// What both export dialogs show of their child process: the job's state and progress, the line
// the dialog shows for it, and the files the last job wrote.
json exportProcessJson(const ExportProcess& job, const std::string& statusText) {
    json outputs = json::array();
    for (const auto& f : job.outputs) outputs.push_back(f.string());
    return {{"status", exportStatusName(job.status)},
            {"statusText", statusText},
            {"progress", job.progress},
            {"outputs", outputs},
            {"outputsExist", exportOutputsExist(job)}};
}

// The export dialog (F12) as drawn: its options, the command it runs, and its job.
json exportJson(const EditorState& s) {
    const ExportJob& job = s.exportJob;
    const ExportOptions& o = job.options;
    json j = {{"shown", s.dialogs.exportStill},
              {"mode", o.pathTraced ? "path" : "fast"},
              {"spp", exportSpp(o)},
              {"denoise", o.denoise},
              {"size", {o.width, o.height}},
              {"output", o.output},
              {"command", commandLine(exportCommand("fraktal", "<preset>", o))},
              {"lights", s.doc.plane ? "" : exportLightsText(s.doc.preset.lighting, o.pathTraced)}};
    j.update(exportProcessJson(job, exportStatusText(job)));
    return j;
}

// The mesh export dialog (File > Export mesh...) as drawn: its options, the command it runs, its
// job and the stage the mesher last named.
json meshExportJson(const EditorState& s) {
    const MeshExportJob& job = s.meshExportJob;
    const MeshExportOptions& o = job.options;
    json j = {{"shown", s.dialogs.exportMesh},
              {"output", o.output},
              {"format", meshFormat(o.output)},
              {"resolution", o.resolution},
              {"voxel", s.doc.plane ? json() : json(meshVoxelSize(s.doc.preset.formula, o.resolution))},
              {"simplify", o.simplify},
              {"printSizeMm", o.printSizeMm},
              {"removeCavities", o.removeCavities},
              {"minThickness", o.minThickness},
              {"vertexColours", o.vertexColours},
              {"available", !s.doc.plane},  // the File menu's item: 3D documents only
              {"optionsError", meshOptionsError(o, s.doc.plane.has_value())},
              {"command", commandLine(meshExportCommand("fraktal", "<preset>", o))},
              {"stage", meshProgressStage(job.log)}};
    j.update(exportProcessJson(job, meshExportStatusText(job)));
    return j;
}

}  // namespace

std::string stateJson(const EditorState& s, int frame, const std::string& compileError, bool viewportSettled,
                      const ViewportStats* viewport, UiDraw ui) {
    const Camera& c = s.doc.preset.camera;
    const auto widgetRect = [](const Layout& l, const std::string& name) {
        const auto at = l.widgetRects.find(name);
        return at == l.widgetRects.end() ? std::array<float, 4>{} : at->second;
    };
    json j;
    j["frame"] = frame;
    j["camera"] = {{"position", {c.position.x, c.position.y, c.position.z}},
                   {"target", {c.target.x, c.target.y, c.target.z}}};
    // The CPU DE at the eye: > 0 outside the surface (null for formulas with GLSL blocks, and for a
    // 2D document, whose unused 3D preset has no estimator).
    const Formula& f = s.doc.preset.formula;
    j["eyeDistance"] = !s.doc.plane && f.cpuEvaluable() ? json(distanceEstimate(f, c.position)) : json();
    j["cameraGesture"] = s.cameraGesture;
    j["uiDraw"] = uiDrawName(ui);  // how this frame drew the window (viewport/ui_redraw.hpp)
    j["shortcutHelp"] = s.panels.help;
    j["tour"] = {{"shown", s.panels.tour}, {"text", s.panels.tourText.size()}};
    j["blockEditorOpen"] = s.customBlockEditor.open;
    // The GLSL block window's errors, each on the line of the code it marks (0: no line).
    json blockErrors = json::array();
    for (const SourceError& e : blockEditorErrors(s.customBlockEditor, compileError))
        blockErrors.push_back({{"line", e.line}, {"message", e.message}});
    j["blockEditor"] = {{"id", s.customBlockEditor.definition.id},
                        {"wholeDE", s.customBlockEditor.definition.wholeDE},
                        {"category", std::string(categoryName(s.customBlockEditor.definition.category))},
                        {"cursorLine", s.customBlockEditor.source.cursorLine},
                        {"firstLineInView", s.customBlockEditor.source.firstLineInView},
                        {"refusal", s.customBlockEditor.error},
                        {"errors", blockErrors}};
    j["flyMode"] = s.cameraControls.mode == CameraMode::Fly;
    j["undoDepth"] = s.history.undoDepth();
    j["redoDepth"] = s.history.redoDepth();
    j["undoLabel"] = s.history.undoLabel();
    j["redoLabel"] = s.history.redoLabel();
    j["viewport"] = {s.layout.viewportX, s.layout.viewportY, s.layout.viewportW, s.layout.viewportH};
    j["window"] = {{"position", {s.window.x, s.window.y}}, {"size", {s.window.width, s.window.height}}};
    j["panels"] = {{"formula", s.panels.formula},
                   {"scene", s.panels.sidebar},
                   {"collapsed", s.panels.collapsed},
                   {"columnWidth", s.layout.leftWidth},
                   {"formulaHeight", s.layout.formulaHeight}};
    j["title"] = windowTitle(s);
    const FileBrowser& b = s.dialogs.browser;
    json folders = json::array();
    for (const auto& f : recentFolders(s.file.recent)) folders.push_back(f.string());
    j["fileBrowser"] = {{"shown", b.shown},
                        {"fieldActive", b.fieldActive},
                        {"saving", b.saving},
                        {"folder", b.folder.string()},
                        {"name", b.name},
                        {"error", b.error},
                        {"replaceAsked", !b.replace.empty()},
                        {"recentFolders", folders},
                        {"recentFiles", s.file.recent}};
    // The Presets tab's thumbnails: how many, rendered, that cannot render, and whether the
    // frames still render them.
    int rendered = 0, failed = 0;
    for (const Thumbnail& t : s.browser.entries) rendered += t.texture != 0, failed += t.failed;
    j["presetBrowser"] = {{"entries", s.browser.entries.size()},
                          {"rendered", rendered},
                          {"failed", failed},
                          {"rendering", s.browser.rendering}};
    j["status"] = {{"text", s.status.text},
                   {"error", s.status.error},
                   // On screen now (the status line shows a message for a few seconds).
                   {"shown", !s.status.text.empty() && s.now <= s.status.until}};
    j["compileError"] = compileError;
    j["viewportSettled"] = viewportSettled;
    // A structure edit compiles in the background while the last image stays settled on screen.
    j["viewportCompiling"] = viewport && viewport->compiling;
    // The render mode (ViewSettings::pathTraceAtRest) and what the viewport shows: "path" with its
    // samples per pixel once the view rests in the path-traced mode, else "fast" with 0.
    if (viewport)
        j["viewportRender"] = {{"mode", s.doc.view.pathTraceAtRest ? "path" : "fast"},
                               {"showing", viewport->pathTracing ? "path" : "fast"},
                               {"pathSpp", viewport->pathTracing ? viewport->pathSamples : 0},
                               {"pathSppCap", s.doc.view.pathSppCap},
                               // The fast mode's samples per pixel and the cap it stops at (the
                               // document's, or `fraktal edit --aa-cap` where that is lower).
                               {"aaSamples", viewport->aaLevel},
                               {"aaCap", viewport->aaCap},
                               {"modeCombo", widgetRect(s.layout, "Render mode")}};
    j["sceneTab"] = s.layout.sceneTab;
    j["popupOpen"] = s.layout.popupOpen;
    // Window events queued for later frames (imgui_input.hpp): tests wait until none are.
    j["inputPending"] = s.input.pendingCount();
    j["widgets"] = s.layout.widgetRects;
    j["timeline"] = timelineJson(s.timeline);
    j["selectedNode"] = s.selectedNode;
    // The node list's rows as it names them.
    json rows = json::array();
    for (size_t i = 0; i < s.doc.preset.formula.nodes.size(); ++i)
        if (s.doc.preset.formula.nodes[i].block) rows.push_back(nodeLabel(s.doc.preset.formula.nodes[i], int(i)));
    j["nodeLabels"] = rows;
    // The step factor the check measured after the last structure change (AutoStepFactor).
    const AutoStepFactor& a = s.stepFactor;
    j["stepFactor"] = {{"measured", a.measured},
                       {"rays", a.rays},
                       {"measuring", a.measuring()},
                       {"refining", a.refining()},
                       {"overridden", a.overridden},
                       {"noHits", a.noHits},
                       {"noSafeFactor", a.noSafeFactor},
                       {"worst", a.worst},
                       {"speed", a.speed},
                       // The step the DE step factor section names as jumping (-1: none).
                       {"jumpingStep", firstJumpingStep(s.doc.preset.formula.nodes)}};
    // Why the stack is slow (SlowStackAdvice): the text the Formula panel shows and its offer.
    const SlowStackAdvice& slow = s.slowStack;
    j["slowStack"] = {{"measuring", slow.measuring()},
                      {"text", slow.text},
                      {"block", slow.shown ? slow.shown->block : -1},
                      {"faster", slow.shown && slow.shown->faster
                                     ? json{{"estimator", std::string(slow.shown->faster->estimator.block->id)},
                                            {"bailout", slow.shown->faster->bailout},
                                            {"deFactor", slow.shown->faster->deFactor}}
                                     : json(nullptr)}};
    // The parameter widgets of the selected node as drawn (window coordinates) and the help text
    // of the parameter tooltip shown, as the widget wrote them this frame.
    json widgets = json::array();
    for (const auto& w : s.paramWidgets.widgets)
        widgets.push_back({{"name", w.name}, {"label", w.label}, {"rect", {w.x, w.y, w.w, w.h}}});
    j["paramWidgets"] = widgets;
    json groups = json::array();
    for (const auto& [name, first] : s.paramWidgets.groups) groups.push_back({{"name", name}, {"firstWidget", first}});
    j["paramGroups"] = groups;
    j["tooltipParam"] = s.paramWidgets.tooltipParam;
    j["tooltip"] = s.paramWidgets.tooltip;
    j["lights"] = lightsJson(s.doc.preset.lighting, s.lights);
    j["exportDialog"] = exportJson(s);
    j["meshExportDialog"] = meshExportJson(s);
    j["document"] = json::parse(fingerprint(s.doc));
    j["fragPresets"] = {{"names", s.fragPresets.names}, {"applied", s.fragPresets.applied}};
    // Text cut by the edge of its window, cell or box this frame (widgets/text_fit.hpp): the
    // layout tests hold it empty at the default window sizes.
    json clipped = json::array();
    for (const ClippedText& c : clippedText())
        clipped.push_back({{"window", c.window}, {"text", c.text}, {"hidden", c.hidden}});
    j["clippedText"] = clipped;
    // Text the editor shows may hold bytes that are not UTF-8 (a file's name, an error quoting a
    // binary file): they are replaced, never a reason to write no state.
    return j.dump(1, ' ', false, json::error_handler_t::replace);
}

void writeStateFile(const std::filesystem::path& file, const std::string& text, std::string& last) {
    if (text == last) return;
    replaceFileForReaders(file, text);
    last = text;
}

std::string frameTickLine(int frame, int pendingInput, bool viewportSettled) {
    return std::to_string(frame) + " " + std::to_string(pendingInput) + " " + (viewportSettled ? "true" : "false") +
           "\n";
}

std::filesystem::path frameTickFile(const std::filesystem::path& stateFile) {
    return std::filesystem::path(stateFile.string() + ".frame");
}

}  // namespace fraktal::editor
