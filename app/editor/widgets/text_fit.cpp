#include "app/editor/widgets/text_fit.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // windows' and tables' layout: ImGui has no public way to ask what it clipped

#include <algorithm>

#include "app/editor/widgets/value_clamp.hpp"

namespace fraktal::editor {

namespace {

// Half a pixel of rounding is not a cut.
constexpr float kTolerance = 1.0f;

// The items recorded in one frame (ImGui keeps one context per program; so does this): kept
// until the next frame records one or asks for the list.
struct Recorded {
    int frame = -1;
    std::vector<ClippedText> items;
};
Recorded gRecorded;

void record(std::string_view text, float hidden) {
    const int frame = ImGui::GetFrameCount();
    if (gRecorded.frame != frame) gRecorded = {frame, {}};
    gRecorded.items.push_back({ImGui::GetCurrentWindow()->Name, std::string(text), hidden});
}

// A window drawn this frame that a person can see (not ImGui's fallback window for items
// drawn outside any Begin, which the editor never shows).
bool shown(const ImGuiWindow& w) {
    return w.Active && !w.Hidden && !w.Collapsed && !std::string_view(w.Name).starts_with("Debug##Default");
}

}  // namespace

void checkComboFits(std::string_view label, std::string_view choice) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const std::string_view visible = visibleLabel(label);
    const float labelWidth = ImGui::CalcTextSize(visible.data(), visible.data() + visible.size()).x;
    // The item's rectangle holds the box, then the label; the box ends in the arrow button.
    float box = ImGui::GetItemRectSize().x;
    if (labelWidth > 0.0f) box -= labelWidth + style.ItemInnerSpacing.x;
    const float room = box - ImGui::GetFrameHeight() - style.FramePadding.x;
    const float width = ImGui::CalcTextSize(choice.data(), choice.data() + choice.size()).x;
    if (width > room + kTolerance) record(std::string(visible) + ": " + std::string(choice), width - room);
    checkItemFits(label);
}

void checkItemFits(std::string_view label) {
    const float edge = ImGui::GetCurrentWindow()->ClipRect.Max.x;
    const float right = ImGui::GetItemRectMax().x;
    const std::string_view visible = visibleLabel(label);
    if (right > edge + kTolerance) record(visible.empty() ? "(an unlabelled item)" : visible, right - edge);
}

std::vector<ClippedText> clippedText() {
    ImGuiContext& g = *GImGui;
    std::vector<ClippedText> out;
    if (gRecorded.frame == g.FrameCount) out = gRecorded.items;
    // Every item's right edge grows the window's CursorMaxPos (ImGui's measure of its content,
    // for scroll bars and auto-sizing): past the visible rectangle, something is cut.
    for (ImGuiWindow* w : g.Windows) {
        if (!shown(*w)) continue;
        const float hidden = w->DC.CursorMaxPos.x - w->InnerClipRect.Max.x;
        if (hidden > kTolerance && !w->ScrollbarX) out.push_back({w->Name, "content wider than the window", hidden});
    }
    // A table cuts each cell's text at the cell's edge; its columns keep how far their content went.
    for (int i = 0; i < g.Tables.GetMapSize(); ++i) {
        const ImGuiTable* t = g.Tables.TryGetMapData(i);
        if (!t || t->LastFrameActive != g.FrameCount || !t->OuterWindow || !shown(*t->OuterWindow)) continue;
        for (int c = 0; c < t->ColumnsCount; ++c) {
            const ImGuiTableColumn& column = t->Columns[c];
            if (!column.IsVisibleX) continue;
            const float hidden = std::max(column.ContentMaxXUnfrozen, column.ContentMaxXFrozen) - column.ClipRect.Max.x;
            if (hidden > kTolerance)
                out.push_back(
                    {t->OuterWindow->Name, "table column " + std::to_string(c + 1) + " wider than its cell", hidden});
        }
    }
    return out;
}

}  // namespace fraktal::editor
