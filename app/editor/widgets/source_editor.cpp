#include "app/editor/widgets/source_editor.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fraktal::editor {

namespace {

constexpr ImU32 kErrorMark = IM_COL32(215, 48, 39, 255);

struct Binding {
    std::string* text;
    SourceEditorState* state;
};

// The byte offset of the start of `line` (from 1) in buf; its end for a line past the last.
int lineStart(const char* buf, int length, int line) {
    int pos = 0;
    for (int l = 1; l < line && pos < length; ++pos)
        if (buf[pos] == '\n') ++l;
    return pos;
}

int editorCallback(ImGuiInputTextCallbackData* data) {
    auto* b = static_cast<Binding*>(data->UserData);
    if (data->EventFlag == ImGuiInputTextFlags_CallbackResize) {
        // ImGui 1.86 edits text in a char buffer: grow the string as the user types.
        b->text->resize(size_t(data->BufTextLen));
        data->Buf = b->text->data();
        return 0;
    }
    SourceEditorState& st = *b->state;
    if (st.goToLine > 0) {
        data->CursorPos = data->SelectionStart = data->SelectionEnd =
            lineStart(data->Buf, data->BufTextLen, st.goToLine);
        st.goToLine = 0;
    }
    st.cursorLine = 1 + int(std::count(data->Buf, data->Buf + data->CursorPos, '\n'));
    return 0;
}

int digits(int n) {
    int d = 1;
    while (n >= 10) n /= 10, ++d;
    return d;
}

}  // namespace

bool sourceEditor(const char* id, std::string& text, const std::vector<int>& errorLines, SourceEditorState& st,
                  float height) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float lineHeight = ImGui::GetFontSize();  // the box's line spacing
    const int lines = 1 + int(std::count(text.begin(), text.end(), '\n'));
    ImGui::PushID(id);
    ImGui::BeginChild("##source", ImVec2(-1.0f, height), true);
    const float viewTop = ImGui::GetWindowPos().y, viewBottom = viewTop + ImGui::GetWindowHeight();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    const float originY = ImGui::GetCursorPosY();  // in the child's content, for its scroll
    // The gutter is as wide as the largest number, at least three digits (lines is under 10^6:
    // the code's bytes are bounded, core/custom_block.hpp).
    const int width = std::clamp(digits(lines), 3, 9);
    char number[16];
    std::snprintf(number, sizeof number, "%0*d", width, 0);
    const float gutterWidth = ImGui::CalcTextSize(number).x + 2.0f * style.FramePadding.x;

    // A cursor moved here from outside (an error's row clicked): scroll to it now, focus the box
    // so that its callback can place the cursor.
    auto lineTop = [&](int line) { return style.FramePadding.y + float(line - 1) * lineHeight; };
    if (st.goToLine > 0) {
        ImGui::SetScrollY(std::max(0.0f, originY + lineTop(st.goToLine) - ImGui::GetWindowHeight() / 3.0f));
        if (!st.active) ImGui::SetKeyboardFocusHere();
    }

    // The box as tall as its lines and one more (a new line does not scroll it), at least the view.
    const float boxHeight =
        std::max(ImGui::GetContentRegionAvail().y, float(lines + 1) * lineHeight + 2.0f * style.FramePadding.y);
    ImGui::SetCursorScreenPos(ImVec2(origin.x + gutterWidth, origin.y));
    Binding binding{&text, &st};
    const bool changed = ImGui::InputTextMultiline(
        "##text", text.data(), text.capacity() + 1, ImVec2(-1.0f, boxHeight),
        ImGuiInputTextFlags_AllowTabInput | ImGuiInputTextFlags_CallbackResize | ImGuiInputTextFlags_CallbackAlways,
        editorCallback, &binding);
    const bool active = ImGui::IsItemActive();
    st.active = active;
    const ImVec2 boxMin = ImGui::GetItemRectMin(), boxMax = ImGui::GetItemRectMax();
    st.textRect = {boxMin.x, std::max(boxMin.y, viewTop), boxMax.x - boxMin.x,
                   std::min(boxMax.y, viewBottom) - std::max(boxMin.y, viewTop)};

    // Keep the cursor's line in view as it moves (arrows, typing), not while the wheel scrolls.
    if (active && st.cursorLine != st.lastCursorLine) {
        const float top = originY + lineTop(st.cursorLine), bottom = top + lineHeight;
        const float scroll = ImGui::GetScrollY(), view = ImGui::GetWindowHeight() - 2.0f * style.WindowPadding.y;
        if (top < scroll) ImGui::SetScrollY(top);
        if (bottom > scroll + view) ImGui::SetScrollY(bottom - view);
    }
    if (active) st.lastCursorLine = st.cursorLine;

    // The gutter: the numbers of the lines in view, an error's on a red mark.
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImU32 plain = ImGui::GetColorU32(ImGuiCol_TextDisabled), current = ImGui::GetColorU32(ImGuiCol_Text);
    st.firstMarkRect = {};
    st.firstLineInView =
        std::clamp(1 + int(std::ceil((viewTop - origin.y - style.FramePadding.y) / lineHeight)), 1, lines);
    const int first = std::max(1, int((viewTop - origin.y) / lineHeight)),
              last = std::min(lines, first + 1 + int((viewBottom - viewTop) / lineHeight) + 1);
    for (int line = first; line <= last; ++line) {
        const float y = origin.y + lineTop(line);
        if (y + lineHeight < viewTop || y > viewBottom) continue;
        const bool error = std::find(errorLines.begin(), errorLines.end(), line) != errorLines.end();
        if (error) {
            const ImVec2 lo(origin.x, y), hi(origin.x + gutterWidth - 2.0f, y + lineHeight);
            draw->AddRectFilled(lo, hi, kErrorMark, 2.0f);
            if (st.firstMarkRect[2] == 0.0f && y >= viewTop && y + lineHeight <= viewBottom)
                st.firstMarkRect = {lo.x, lo.y, hi.x - lo.x, hi.y - lo.y};
        }
        std::snprintf(number, sizeof number, "%*d", width, line % 1000000000);
        const float x = origin.x + gutterWidth - style.FramePadding.x - ImGui::CalcTextSize(number).x;
        draw->AddText(ImVec2(x, y), error ? IM_COL32_WHITE : active && line == st.cursorLine ? current : plain, number);
    }
    ImGui::EndChild();
    ImGui::PopID();
    return changed;
}

}  // namespace fraktal::editor
