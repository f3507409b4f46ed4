// The formula panel (left): iterations and bailout, the node list (select, enable, reorder by
// drag and drop, duplicate, remove, add from a categorised menu), the estimator, and the
// selected node's parameters; under them the objects beside the fractal and the whole fractals
// combined with it. Compile errors are shown under the node they name.
#include <imgui.h>
#include <imgui_stdlib.h>

#include <cstdio>
#include <string>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/state/actions.hpp"
#include "app/editor/timeline/timeline_panel.hpp"
#include "app/editor/widgets/node_list_widgets.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/setting_widgets.hpp"
#include "core/safe_step.hpp"
#include "core/scene/formula_fit.hpp"

namespace fraktal::editor {

namespace {

constexpr const char* kNodePayload = "FRAKTAL_NODE";

// The groups of a custom block's parameters (an imported frag's #group); none for a built-in one.
std::function<std::string(size_t)> customParamGroups(const Formula& f, const BlockDesc& block) {
    const CustomBlock* custom = block.custom ? findCustomBlock(f, block.id) : nullptr;
    if (!custom) return {};
    return [custom](size_t k) {
        const auto& params = custom->definition().params;
        return k < params.size() ? params[k].group : std::string();
    };
}

void addBlockMenu(EditorState& s) {
    Formula& f = s.doc.preset.formula;
    const Category steps[] = {Category::Fold, Category::Transform, Category::Power};
    for (Category c : steps) {
        if (!ImGui::BeginMenu(std::string(categoryName(c)).c_str())) continue;
        std::vector<const BlockDesc*> blocks = blocksIn(c);
        for (const BlockDesc* b : customBlocksIn(f, c)) blocks.push_back(b);  // the formula's GLSL blocks
        if (const BlockDesc* b = blockMenuItems(blocks)) {
            const int at = std::min(s.selectedNode + 1, int(f.nodes.size()));
            if (addNode(s.doc.preset, *b, at)) {
                s.selectedNode = at;
                fitFormulaAfterEdit(s.doc.preset);
            }
        }
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::BeginMenu("Estimator (replaces)")) {
        std::vector<const BlockDesc*> estimators = blocksIn(Category::Estimator);
        for (const BlockDesc* b : customBlocksIn(f, Category::Estimator)) estimators.push_back(b);
        if (const BlockDesc* b = blockMenuItems(estimators, f.estimator.block)) {
            setEstimator(s.doc.preset, *b);
            s.selectedNode = int(f.nodes.size());
        }
        ImGui::EndMenu();
    }
    ImGui::Separator();
    if (ImGui::MenuItem("New GLSL block...")) {
        s.customBlockEditor.definition = newBlockTemplate();
        s.customBlockEditor.source = {};  // the cursor at the top of other code
        s.customBlockEditor.error.clear();
        s.customBlockEditor.open = true;
    }
}

void globalSettings(Formula& f, AutoStepFactor& stepFactor, Layout& layout) {
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    dragClamped("Iterations", &f.iterations, 1, 0.1f, 1, kMaxIterations, "%d");
    helpMarker("How many times the node list runs per point. Parameters update live, without a recompile.");
    const double bailLo = 0.1, bailHi = 1e6, boundLo = 0.01, boundHi = 100.0, facLo = kMinStepFactor,
                 facHi = kMaxStepFactor;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    dragClamped("Bailout", &f.bailout, 1, 0.05f, bailLo, bailHi, "%.4g", ImGuiSliderFlags_Logarithmic);
    helpMarker("The orbit escapes when |p| passes this radius.");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    dragClamped("Bound radius", &f.boundRadius, 1, 0.01f, boundLo, boundHi, "%.3g");
    noteWidgetRect(layout, "Bound radius");
    helpMarker("The fractal lies inside this sphere; rays are clipped to it.");
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
    if (dragClamped("DE factor", &f.deFactor, 1, 0.005f, facLo, facHi, "%.3f")) stepFactor.overridden = true;
    helpMarker(
        "How far a ray steps towards the surface: smaller is safer (no specks or holes) and slower. Measured "
        "after every change of the nodes, unless set by hand (Render tab, Step size).");
}

// A slow stack explains itself (SlowStackAdvice): what keeps the estimate loose, and the faster
// estimator and bailout as one click (one undo step).
void slowStackNotice(EditorState& s) {
    const SlowStackAdvice& advice = s.slowStack;
    if (advice.measuring()) {
        ImGui::TextDisabled("Step factor %.3f: finding out what keeps the estimate loose...", s.stepFactor.measured);
        return;
    }
    if (advice.text.empty()) return;
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(ImVec4(1.0f, 0.8f, 0.35f, 1), "%s", advice.text.c_str());
    ImGui::PopTextWrapPos();
    noteWidgetRect(s.layout, "text:Slow stack");
    if (!advice.shown || !advice.shown->faster) return;
    const Formula& faster = *advice.shown->faster;
    char label[160];
    std::snprintf(label, sizeof label, "Use %s at bailout %g", std::string(faster.estimator.block->label).c_str(),
                  faster.bailout);
    if (ImGui::Button(label)) applyFasterEstimator(s.doc.preset, s.stepFactor, *advice.shown);
    noteWidgetRect(s.layout, "button:Use faster estimator");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("Replace the estimator and bailout, with step factor %.3f (measured). Ctrl+Z undoes it.",
                          faster.deFactor);
}

// The placement of an object, declared as parameters so that it gets the same widgets.
constexpr ParamDecl kObjectCenter{"center", ParamType::Vec3, {0.0, 0.0, 0.0},
                                  -100.0,   100.0,           "Where the object's frame sits."};
constexpr ParamDecl kObjectAxis{
    "axis", ParamType::Vec3, {0.0, 0.0, 1.0}, -1.0, 1.0, "The axis the object is turned about.", true};
constexpr ParamDecl kObjectAngle{"angle",         ParamType::Float,
                                 {0.0, 0.0, 0.0}, -180.0,
                                 180.0,           "How far the object is turned about its axis, in degrees."};

// Objects beside the fractal, under the parameters (a collapsed header by default, so the rows
// above keep their places): each with its operation, shell, placement and parameters.
void objectsSection(EditorState& s) {
    Formula& f = s.doc.preset.formula;
    ImGui::Spacing();
    const std::string title = "Objects beside the fractal (" + std::to_string(f.objects.size()) + ")###objects";
    const bool open = ImGui::CollapsingHeader(title.c_str());
    noteWidgetRect(s.layout, "header:Objects");
    if (!open) return;
    int remove = -1;
    for (size_t j = 0; j < f.objects.size(); ++j) {
        SceneObject& o = f.objects[j];
        ImGui::PushID(int(j));
        const std::string label = std::to_string(j + 1) + ". " + std::string(o.block->label) + " (" +
                                  std::string(kObjectOperationNames[int(o.operation)]) + ")";
        if (ImGui::TreeNodeEx(label.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::Checkbox("On", &o.enabled);
            ImGui::SameLine();
            ImGui::Checkbox("Hollow", &o.hollow);
            helpMarker("Only the object's shell: its distance taken as |d|.");
            ImGui::SameLine();
            if (ImGui::SmallButton("Remove")) remove = int(j);
            int operation = int(o.operation);
            ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
            if (ImGui::Combo("Operation", &operation, "join\0intersect\0carve\0"))
                o.operation = ObjectOperation(operation);
            helpMarker(
                "join: the union with what comes before; intersect: only what lies inside the object (a limit "
                "box); carve: the object cut out.");
            ParamValue angle(o.angle, 0.0, 0.0);
            paramWidget(kObjectCenter, o.center, &s.paramWidgets);
            paramWidget(kObjectAxis, o.axis, &s.paramWidgets);
            if (paramWidget(kObjectAngle, angle, &s.paramWidgets)) o.angle = angle.x;
            for (size_t k = 0; k < o.block->params.size(); ++k)
                paramWidget(o.block->params[k], o.values[k], &s.paramWidgets);
            // A reflectance (linear Rec.709): the preset refuses one above 1.
            if (colorEdit("Colour", o.color, nullptr)) o.color = clamp(o.color, 0.0, 1.0);
            noteWidgetRect(s.layout, "color:Object " + std::to_string(j + 1));
            helpMarker("The object's own colour (its reflectance), whatever the fractal's palette does.");
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (remove >= 0) removeObject(f, remove);
    ImGui::BeginDisabled(int(f.objects.size()) >= kMaxObjects);
    if (ImGui::Button("Add object...")) ImGui::OpenPopup("add_object");
    ImGui::EndDisabled();
    noteWidgetRect(s.layout, "button:Add object");
    if (ImGui::BeginPopup("add_object")) {
        for (const ObjectDesc& kind : allObjects()) {
            if (ImGui::MenuItem(std::string(kind.label).c_str())) addObject(s.doc.preset, kind);
            noteWidgetRect(s.layout, "menu:Object " + std::string(kind.label));
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(kind.help).c_str());
        }
        ImGui::EndPopup();
    }
}

constexpr ParamDecl kFractalScale{"scale",         ParamType::Float,
                                  {1.0, 0.0, 0.0}, 0.01,
                                  100.0,           "The point is multiplied by it: above 1 the fractal shrinks."};
constexpr ParamDecl kFractalRepeat{"repeat",        ParamType::Vec3,
                                   {0.0, 0.0, 0.0}, 0.0,
                                   100.0,           "Repeats the fractal in cells this wide, per axis (0: once)."};

// The widgets of a fractal's placement (FractalPlacement): the objects' center, axis and angle,
// then scale and repeat.
void placementWidgets(EditorState& s, FractalPlacement& place) {
    ParamValue angle(place.angle, 0.0, 0.0), scale(place.scale, 0.0, 0.0);
    paramWidget(kObjectCenter, place.center, &s.paramWidgets);
    paramWidget(kObjectAxis, place.axis, &s.paramWidgets);
    if (paramWidget(kObjectAngle, angle, &s.paramWidgets)) place.angle = angle.x;
    if (paramWidget(kFractalScale, scale, &s.paramWidgets)) place.scale = scale.x;
    paramWidget(kFractalRepeat, place.repeat, &s.paramWidgets);
}

// A node's parameters under its block's label, without the selection or keyframes of the node
// list: a combined fractal's nodes are edited in place.
void nodeParamWidgets(EditorState& s, Node& node, int index) {
    if (!node.block || node.block->params.empty()) return;
    ImGui::PushID(index);
    ImGui::TextDisabled("%s", std::string(node.block->label).c_str());
    for (size_t k = 0; k < node.block->params.size(); ++k)
        paramWidget(node.block->params[k], node.values[k], &s.paramWidgets);
    ImGui::PopID();
}

// Whole fractals combined with the first (Formula::fractals), under the objects (a collapsed
// header by default, so the rows above keep their places): the first fractal's placement, then
// each combined fractal with its operation, settings, placement and its nodes' parameters.
// Structure edits (add, remove, on/off, operation) recompile; values are uniforms.
void fractalsSection(EditorState& s) {
    Formula& f = s.doc.preset.formula;
    ImGui::Spacing();
    const std::string title = "Fractals combined with this one (" + std::to_string(f.fractals.size()) + ")###fractals";
    const bool open = ImGui::CollapsingHeader(title.c_str());
    noteWidgetRect(s.layout, "header:Fractals");
    if (!open) return;
    if (!f.fractals.empty() || !f.placement.identity()) {
        if (ImGui::TreeNodeEx("1. This fractal's placement", ImGuiTreeNodeFlags_DefaultOpen)) {
            placementWidgets(s, f.placement);
            ImGui::TreePop();
        }
    }
    int remove = -1;
    const double bailLo = 0.1, bailHi = 1e6, facLo = kMinStepFactor, facHi = kMaxStepFactor;
    for (size_t j = 0; j < f.fractals.size(); ++j) {
        CombinedFractal& c = f.fractals[j];
        Formula& g = c.formula;
        ImGui::PushID(int(j));
        const std::string label = std::to_string(j + 2) + ". " +
                                  std::string(g.estimator.block ? g.estimator.block->label : "(none)") + " (" +
                                  std::string(kObjectOperationNames[int(c.operation)]) + ")";
        if (ImGui::TreeNodeEx(label.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
            ImGui::Checkbox("On", &c.enabled);
            ImGui::SameLine();
            if (ImGui::SmallButton("Remove")) remove = int(j);
            int operation = int(c.operation);
            ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
            if (ImGui::Combo("Operation", &operation, "join\0intersect\0carve\0"))
                c.operation = ObjectOperation(operation);
            helpMarker(
                "join: the union with the fractals before; intersect: only what lies inside this one too; carve: "
                "this one cut out of them.");
            ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
            dragClamped("Iterations", &g.iterations, 1, 0.1f, 1, kMaxIterations, "%d");
            ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
            dragClamped("Bailout", &g.bailout, 1, 0.05f, bailLo, bailHi, "%.4g", ImGuiSliderFlags_Logarithmic);
            ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.55f);
            dragClamped("DE factor", &g.deFactor, 1, 0.005f, facLo, facHi, "%.3f");
            helpMarker(
                "Multiplies this fractal's distance estimate alone; the automatic step factor sets the first's.");
            placementWidgets(s, g.placement);
            for (size_t k = 0; k < g.nodes.size(); ++k) nodeParamWidgets(s, g.nodes[k], int(k));
            nodeParamWidgets(s, g.estimator, int(g.nodes.size()));
            ImGui::TreePop();
        }
        ImGui::PopID();
    }
    if (remove >= 0 && removeFractal(f, remove)) fitFormulaAfterEdit(s.doc.preset);
    ImGui::BeginDisabled(int(f.fractals.size()) >= kMaxCombinedFractals);
    if (ImGui::Button("Add fractal...")) {
        s.fractalChoices = combinableFractals(s.browser.folders);
        ImGui::OpenPopup("add_fractal");
    }
    ImGui::EndDisabled();
    noteWidgetRect(s.layout, "button:Add fractal");
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip("Combine a preset's fractal with this one (joined, at its own placement).");
    if (ImGui::BeginPopup("add_fractal")) {
        const std::vector<FractalChoice>& choices = s.fractalChoices;
        if (choices.empty()) ImGui::TextDisabled("No preset with built-in blocks found.");
        for (size_t i = 0; i < choices.size(); ++i) {
            ImGui::PushID(int(i));
            if (ImGui::MenuItem(choices[i].name.c_str()) && addFractal(f, choices[i].formula))
                fitFormulaAfterEdit(s.doc.preset);
            noteWidgetRect(s.layout, "menu:Fractal " + choices[i].name);
            ImGui::PopID();
        }
        ImGui::EndPopup();
    }
}

// A checkbox that sets the hit rule to `rule` when ticked and back to the plain surface when
// cleared; its rectangle is noted as "checkbox:LABEL" for the user stories.
void hitRuleCheckbox(EditorState& s, HitRule& hitRule, HitRule rule, const char* label, const char* help) {
    bool on = hitRule == rule;
    if (ImGui::Checkbox(label, &on)) hitRule = on ? rule : HitRule::Surface;
    noteWidgetRect(s.layout, std::string("checkbox:") + label);
    helpMarker(help);
}

}  // namespace

// An opened frag's #presets, as FragM lists them: choosing one applies its values (the DE's
// parameters, the camera, the raytracer's settings) as one undo step.
void fragPresetCombo(EditorState& s) {
    const FragPresets& presets = s.fragPresets;
    const char* shown = presets.applied.empty() ? "(none)" : presets.applied.c_str();
    std::string chosen;
    if (ImGui::BeginCombo("Frag preset", shown)) {
        for (const std::string& name : presets.names)
            if (ImGui::Selectable(name.c_str(), name == presets.applied)) chosen = name;
        ImGui::EndCombo();
    }
    noteWidgetRect(s.layout, "combo:Frag preset");
    helpMarker(
        "The frag's own #preset blocks: choosing one sets the values it holds (parameters, camera, "
        "lights), as Fragmentarium does.");
    if (!chosen.empty()) applyFragPreset(s, chosen);
}

void beginFormulaWindow(EditorState& s) { beginSideColumnWindow(s, "Formula", &s.panels.formula, true); }

void drawFormulaPanel(EditorState& s, const ViewportView& v) {
    if (!sideColumnShows(s.panels, true)) return;
    beginFormulaWindow(s);
    Formula& f = s.doc.preset.formula;
    s.selectedNode = std::clamp(s.selectedNode, 0, int(f.nodes.size()));

    ImGui::SetNextItemWidth(-1);
    ImGui::InputTextWithHint("##name", "Preset name", &s.doc.preset.name);
    globalSettings(f, s.stepFactor, s.layout);
    ImGui::Spacing();
    sectionHeader("Node list");

    const std::string& error = v.compileError();
    const int errorNode = error.empty() ? -2 : nodeNamedInLog(error, int(f.nodes.size()));
    NodeListRequest req;
    for (int i = 0; i < int(f.nodes.size()); ++i) {
        if (nodeRow(f.nodes[size_t(i)], i, s.selectedNode == i, i == errorNode ? &error : nullptr, kNodePayload, req))
            s.selectedNode = i;
        // The row's Del button, last on the row's line (an error, when shown, comes after it).
        if (i != errorNode) noteWidgetRect(s.layout, "button:Del " + std::to_string(i + 1));
    }

    // The estimator closes the list; it is always last and cannot be removed, only replaced.
    ImGui::PushID("estimator");
    const int est = int(f.nodes.size());
    if (errorNode == est) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    if (ImGui::Selectable(
            (std::to_string(est + 1) + ". => " + std::string(f.estimator.block ? f.estimator.block->label : "(none)"))
                .c_str(),
            s.selectedNode == est))
        s.selectedNode = est;
    noteWidgetRect(s.layout, "row:estimator");
    if (errorNode == est) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("The closing estimator: turns the final orbit into a distance.");
    if (errorNode == est) errorUnder(error);
    ImGui::PopID();
    if (!error.empty() && errorNode == -1) errorUnder(error);

    // A whole DE (an imported frag) is the whole formula: no step goes before it.
    const bool wholeDE = wholeDEFormula(f);
    ImGui::BeginDisabled(wholeDE);
    if (ImGui::Button("Add block...")) ImGui::OpenPopup("add_block");
    ImGui::EndDisabled();
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(wholeDE ? "This formula's distance is one piece of code (an imported frag): blocks cannot "
                                    "be added before it"
                                  : "Insert a block after the selected node");
    if (ImGui::BeginPopup("add_block")) {
        addBlockMenu(s);
        ImGui::EndPopup();
    }
    const bool nodeSelected = s.selectedNode < int(f.nodes.size());
    ImGui::SameLine();
    ImGui::BeginDisabled(!nodeSelected || s.selectedNode == 0);
    if (ImGui::ArrowButton("##up", ImGuiDir_Up)) req.moveFrom = s.selectedNode, req.moveTo = s.selectedNode - 1;
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(!nodeSelected || s.selectedNode + 1 >= int(f.nodes.size()));
    if (ImGui::ArrowButton("##down", ImGuiDir_Down)) req.moveFrom = s.selectedNode, req.moveTo = s.selectedNode + 1;
    ImGui::EndDisabled();

    // Apply list edits after drawing the list, so no row is drawn from a moved vector.
    if (req.moveFrom >= 0 && moveNode(s.doc.preset, req.moveFrom, req.moveTo)) s.selectedNode = req.moveTo;
    if (req.duplicate >= 0 && duplicateNode(s.doc.preset, req.duplicate)) s.selectedNode = req.duplicate + 1;
    if (req.remove >= 0 && removeNode(s.doc.preset, req.remove)) {
        s.selectedNode = std::max(0, std::min(req.remove, int(f.nodes.size()) - 1));
        fitFormulaAfterEdit(s.doc.preset);
    }
    s.selectedNode = std::clamp(s.selectedNode, 0, int(f.nodes.size()));
    // A frag's own presets, by its code's row (which holds their values).
    if (wholeDE && !s.fragPresets.names.empty()) fragPresetCombo(s);
    // Under the list the artist just edited, above the parameters.
    slowStackNotice(s);

    ImGui::Spacing();
    sectionHeader("Parameters");
    const bool estimatorSelected = s.selectedNode == int(f.nodes.size());
    const Node& selected = estimatorSelected ? f.estimator : f.nodes[size_t(s.selectedNode)];
    Node& shown = estimatorSelected ? f.estimator : f.nodes[size_t(s.selectedNode)];
    nodeParameters(
        shown, estimatorSelected, s.paramWidgets,
        [&](size_t k) {
            const std::string name(shown.block->params[k].name);
            const ParamValue& v = shown.values[k];
            keyMarker(
                s, estimatorSelected ? estimatorParamTarget(name) : paramTarget(s.selectedNode, name),
                isScalar(shown.block->params[k].type) ? std::vector<double>{v.x} : std::vector<double>{v.x, v.y, v.z});
        },
        customParamGroups(f, *shown.block));
    if (estimatorSelected) {
        // Under the estimator's own parameters, so that the rows above keep their places.
        // The hit rules other than the plain surface, each a checkbox (ticking one unticks the other).
        hitRuleCheckbox(s, f.hitRule, HitRule::InsideOnly, "Hit only inside",
                        "Rays stop only where the point is inside (the orbit stays bounded for every iteration, or "
                        "the estimate is below 0); the estimate only sizes the steps. Mandelbulber2's iteration "
                        "threshold mode: the surface of spiky sets (hypercomplex, power-2 bulbs), whose estimate is "
                        "small far from them.");
        hitRuleCheckbox(s, f.hitRule, HitRule::InteriorWalls, "Hit interior walls",
                        "Rays stop only just outside the set; inside it they crawl on until they come out. A camera "
                        "inside the set, or an object that cuts it open (intersect), shows the walls of its inner "
                        "cavities. Mandelbulber2's interior mode; slow where rays cross much of the set.");
    }
    if (selected.block->custom) {
        if (const CustomBlock* b = findCustomBlock(f, selected.block->id)) {
            const bool edit = ImGui::Button("Edit GLSL...");
            noteWidgetRect(s.layout, "button:Edit GLSL");
            if (edit) {
                s.customBlockEditor.definition = b->definition();
                s.customBlockEditor.source = {};  // the cursor at the top of other code
                s.customBlockEditor.error.clear();
                s.customBlockEditor.open = true;
            }
        }
    }
    objectsSection(s);
    fractalsSection(s);
    // A node selected with fewer parameters below it leaves the rows above where they were.
    keepWindowScroll();
    ImGui::End();
}

}  // namespace fraktal::editor
