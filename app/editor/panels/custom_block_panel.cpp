// The GLSL block editor window: id, category, help, the parameter list (name, type, default,
// range, help; an imported frag's groups) and the GLSL in a code editor with line numbers.
// Apply adds the block to the formula or replaces the one with the same id (nodes using it are
// rebound). A refused Apply's reason and the compile errors of the block's code are listed under
// it and marked on their lines; they also show under the nodes that use it, as for built-in
// blocks. A block library file stores every custom block of the formula.
#include <imgui.h>

#include <fstream>
#include <sstream>

#include "app/editor/document/formula_edits.hpp"
#include "app/editor/document/preset_files.hpp"
#include "app/editor/panels/panels.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/source_editor.hpp"
#include "core/atomic_file.hpp"
#include "core/whole_de.hpp"

namespace fraktal::editor {

CustomBlock::Definition newBlockTemplate() {
    CustomBlock::Definition d;
    d.id = "my_twist";
    d.label = "My twist";
    d.help = "Rotates about y by an angle that grows with y.";
    d.category = Category::Transform;
    CustomBlock::Definition::Param rate;
    rate.name = "rate";
    rate.help = "radians per unit of y";
    rate.defaultValue = vec3(0.5);
    rate.min = -4.0;
    rate.max = 4.0;
    d.params.push_back(rate);
    d.glsl =
        "float a = rate * p.y;\n"
        "float s = sin(a), k = cos(a);\n"
        "p.xz = vec2(k * p.x - s * p.z, s * p.x + k * p.z);\n";
    return d;
}

namespace {

// ImGui 1.86 edits text in a char buffer: grow the string as the user types.
int growString(ImGuiInputTextCallbackData* data) {
    if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
        auto* text = static_cast<std::string*>(data->UserData);
        text->resize(size_t(data->BufTextLen));
        data->Buf = text->data();
    }
    return 0;
}

bool inputString(const char* label, std::string& text, bool multiline = false, float height = 0.0f) {
    const ImGuiInputTextFlags flags = ImGuiInputTextFlags_CallbackResize;
    if (multiline)
        return ImGui::InputTextMultiline(label, text.data(), text.capacity() + 1, ImVec2(-1.0f, height),
                                         flags | ImGuiInputTextFlags_AllowTabInput, growString, &text);
    return ImGui::InputText(label, text.data(), text.capacity() + 1, flags, growString, &text);
}

void parameterRows(CustomBlock::Definition& d) {
    int remove = -1;
    for (size_t i = 0; i < d.params.size(); ++i) {
        auto& p = d.params[i];
        // An imported frag's #group, as the Formula panel heads its sliders.
        if (!p.group.empty() && (i == 0 || d.params[i - 1].group != p.group))
            ImGui::TextDisabled("%s", p.group.c_str());
        ImGui::PushID(int(i));
        ImGui::SetNextItemWidth(110.0f);
        inputString("##name", p.name);
        ImGui::SameLine();
        int type = p.type == ParamType::Vec3 ? 1 : p.type == ParamType::Toggle ? 2 : 0;
        ImGui::SetNextItemWidth(70.0f);
        if (ImGui::Combo("##type", &type, "float\0vec3\0toggle\0")) {
            p.type = type == 1 ? ParamType::Vec3 : type == 2 ? ParamType::Toggle : ParamType::Float;
            // A toggle is 0 or 1: its range and default follow.
            if (p.type == ParamType::Toggle) {
                p.min = 0.0;
                p.max = 1.0;
                p.defaultValue = vec3(p.defaultValue.x > 0.5 ? 1.0 : 0.0, 0.0, 0.0);
            }
        }
        ImGui::SameLine();
        ImGui::SetNextItemWidth(160.0f);
        if (p.type == ParamType::Toggle) {
            bool on = p.defaultValue.x > 0.5;
            if (ImGui::Checkbox("##default", &on)) p.defaultValue.x = on ? 1.0 : 0.0;
        } else if (p.type == ParamType::Vec3) {
            ImGui::DragScalarN("##default", ImGuiDataType_Double, &p.defaultValue.x, 3, 0.01f);
        } else {
            ImGui::DragScalar("##default", ImGuiDataType_Double, &p.defaultValue.x, 0.01f);
        }
        ImGui::BeginDisabled(p.type == ParamType::Toggle);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(70.0f);
        ImGui::DragScalar("##min", ImGuiDataType_Double, &p.min, 0.01f);
        ImGui::SameLine();
        ImGui::SetNextItemWidth(70.0f);
        ImGui::DragScalar("##max", ImGuiDataType_Double, &p.max, 0.01f);
        ImGui::EndDisabled();
        ImGui::SameLine();
        if (ImGui::SmallButton("x")) remove = int(i);
        ImGui::SetNextItemWidth(-1.0f);
        inputString("##help", p.help);
        ImGui::PopID();
    }
    if (remove >= 0) d.params.erase(d.params.begin() + remove);
    if (int(d.params.size()) < (d.wholeDE ? kMaxWholeDEParams : kMaxCustomParams) &&
        ImGui::SmallButton("+ parameter")) {
        CustomBlock::Definition::Param p;
        p.name = "param" + std::to_string(d.params.size() + 1);
        d.params.push_back(p);
    }
}

void libraryButtons(EditorState& s) {
    CustomBlockEditor& e = s.customBlockEditor;
    Formula& f = s.doc.preset.formula;
    if (e.library.empty()) e.library = configFolder() / "blocks.json";
    std::string path = e.library.string();
    ImGui::SetNextItemWidth(-170.0f);
    if (inputString("##library", path)) e.library = path;
    ImGui::SameLine();
    if (ImGui::Button("Save library")) {
        try {
            writeFileAtomically(e.library, serializeBlockLibrary(f.customBlocks), true);
            e.libraryMessage = "saved " + std::to_string(f.customBlocks.size()) + " blocks to " + e.library.string();
        } catch (const std::exception& ex) {
            e.libraryMessage = ex.what();
        }
    }
    ImGui::SameLine();
    if (ImGui::Button("Load")) {
        try {
            int added = 0;
            for (const auto& b : loadBlockLibrary(e.library.string())) {
                const std::string why = upsertCustomBlock(f, b->definition());
                if (!why.empty()) throw std::runtime_error(b->definition().id + ": " + why);
                ++added;
            }
            e.libraryMessage = "loaded " + std::to_string(added) + " blocks from " + e.library.string();
        } catch (const std::exception& ex) {
            e.libraryMessage = ex.what();
        }
    }
    if (!e.libraryMessage.empty()) ImGui::TextWrapped("%s", e.libraryMessage.c_str());
}

// Id, label, category (fixed for a whole DE, which computes the whole distance) and help.
void identityFields(CustomBlock::Definition& d) {
    inputString("Id", d.id);
    inputString("Label", d.label);
    if (d.wholeDE) {
        ImGui::TextDisabled("Category: estimator (a whole DE computes the distance)");
    } else {
        int category = int(d.category);
        ImGui::Combo("Category", &category, "fold\0transform\0power\0estimator\0");
        d.category = Category(category);
    }
    if (d.category == Category::Estimator) {
        int membership = d.membership == Membership::EscapeTime ? 1 : 0;
        ImGui::Combo("Inside is", &membership, "distance <= 0\0the orbit stays bounded\0");
        d.membership = membership ? Membership::EscapeTime : Membership::Distance;
    }
    inputString("Help", d.help);
}

// What the code may hold, above it.
const char* codeHint(const CustomBlock::Definition& d) {
    if (d.wholeDE)
        return "GLSL: functions, globals and #define lines that define float DE(vec3 p), returning the distance. "
               "Loops, functions and #define are allowed (each DE call's loops are bounded); the parameters are "
               "in scope by name.";
    if (d.category == Category::Estimator)
        return "GLSL: statements over vec4 p (w: running scale) and c, ending in return <distance>; "
               "loops and the preprocessor are not allowed: every call is bounded.";
    return "GLSL: statements over inout vec4 p (w: running scale) and vec3 c; loops and the preprocessor are "
           "not allowed: every call is bounded.";
}

void applyDefinition(EditorState& s) {
    CustomBlockEditor& e = s.customBlockEditor;
    const CustomBlock::Definition& d = e.definition;
    Formula& f = s.doc.preset.formula;
    const bool isNew = !findCustomBlock(f, d.id);
    e.error = upsertCustomBlock(f, d);
    if (e.error.empty() && isNew) {
        const CustomBlock* b = findCustomBlock(f, d.id);
        if (b->desc().isEstimator()) {
            setEstimator(s.doc.preset, b->desc());
            s.selectedNode = int(f.nodes.size());
        } else {
            const int at = std::min(s.selectedNode + 1, int(f.nodes.size()));
            if (addNode(s.doc.preset, b->desc(), at)) s.selectedNode = at;
        }
    }
}

const ImVec4 kErrorText(1.0f, 0.45f, 0.4f, 1.0f);

// The errors on the code's lines, a row each ("line 12: 'foo' : undeclared identifier"); a click
// puts the cursor on its line.
void errorRows(EditorState& s, const std::vector<SourceError>& errors) {
    CustomBlockEditor& e = s.customBlockEditor;
    for (size_t i = 0; i < errors.size(); ++i) {
        const SourceError& err = errors[i];
        const std::string row =
            (err.line > 0 ? "line " + std::to_string(err.line) + ": " : std::string()) + err.message;
        ImGui::PushID(int(i));
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorText);
        if (ImGui::Selectable(row.c_str()) && err.line > 0) e.source.goToLine = err.line;
        ImGui::PopStyleColor();
        ImGui::PopID();
        if (i == 0) noteWidgetRect(s.layout, "glsl:first error");
        if (ImGui::IsItemHovered() && err.line > 0) ImGui::SetTooltip("Go to line %d", err.line);
    }
}

}  // namespace

void drawCustomBlockEditor(EditorState& s, const std::string& compileError) {
    CustomBlockEditor& e = s.customBlockEditor;
    if (!e.open || s.doc.plane) return;
    ImGui::SetNextWindowSize(ImVec2(620, 700), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("GLSL block", &e.open)) {
        ImGui::End();
        return;
    }
    const ImVec2 at = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
    s.layout.widgetRects["window:GLSL block"] = {at.x, at.y, size.x, size.y};
    CustomBlock::Definition& d = e.definition;
    identityFields(d);
    // A frag's tens of parameters would push the code out of sight: folded until asked for.
    if (ImGui::CollapsingHeader("Parameters (name, type, default, min, max; help below)",
                                d.wholeDE ? 0 : ImGuiTreeNodeFlags_DefaultOpen))
        parameterRows(d);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", codeHint(d));
    ImGui::PopTextWrapPos();

    const std::vector<SourceError> errors = blockEditorErrors(e, compileError);
    std::vector<int> errorLines;
    for (const SourceError& err : errors)
        if (err.line > 0) errorLines.push_back(err.line);
    // The code takes what the window leaves: below it the Apply row, the errors (up to six rows
    // before they scroll with the window) and the library's header.
    const float row = ImGui::GetFrameHeightWithSpacing();
    const float below = row * (3.0f + float(std::min<size_t>(errors.size(), 6)) + (e.error.empty() ? 0.0f : 1.0f));
    const float codeHeight = std::max(ImGui::GetTextLineHeight() * 12.0f, ImGui::GetContentRegionAvail().y - below);
    sourceEditor("glsl", d.glsl, errorLines, e.source, codeHeight);
    noteWidgetRect(s.layout, "glsl:source");
    s.layout.widgetRects["glsl:text"] = e.source.textRect;
    s.layout.widgetRects["glsl:first error mark"] = e.source.firstMarkRect;

    const bool apply =
        ImGui::Button(findCustomBlock(s.doc.preset.formula, d.id) ? "Apply (replace)" : "Apply (add to the formula)");
    noteWidgetRect(s.layout, "button:Apply GLSL");
    if (apply) applyDefinition(s);
    ImGui::SameLine();
    ImGui::TextDisabled("line %d", e.source.cursorLine);
    // A refusal of another field than the code (an id, a parameter) has no line to mark.
    if (!e.error.empty() && validationSourceErrors(e.error).empty())
        ImGui::TextColored(kErrorText, "%s", e.error.c_str());
    // The compile errors are of the block as last applied; the viewport keeps its last good image.
    errorRows(s, errors);
    if (ImGui::CollapsingHeader("Block library")) libraryButtons(s);
    ImGui::End();
}

}  // namespace fraktal::editor
