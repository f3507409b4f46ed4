// A code editor for GLSL: the text in a box as tall as its lines, beside a gutter of line
// numbers that scrolls with it, the lines with an error marked red in the gutter. ImGui 1.86's
// multi-line box draws no numbers and has no call that moves its cursor, so the box sits in a
// scrolling child of its own height (the gutter and the text scroll as one) and a callback reads
// and, when asked (goToLine), sets the cursor.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace fraktal::editor {

struct SourceEditorState {
    int cursorLine = 1;      // the line the cursor is on, from 1
    int goToLine = 0;        // > 0: move the cursor to the start of this line and scroll it into view
    bool active = false;     // the text box has the keyboard
    int lastCursorLine = 0;  // to scroll only when the cursor moved to another line, not against the wheel
    // The gutter mark of the first error line drawn, in screen pixels {x, y, w, h}; zero when no
    // marked line is in view (the Xvfb stories look at it).
    std::array<float, 4> firstMarkRect{};
    std::array<float, 4> textRect{};  // the visible part of the text box
    int firstLineInView = 1;          // the topmost line shown whole
};

// Draws the editor `height` pixels tall and the full width; returns whether the text changed.
// `errorLines` are numbered from 1.
bool sourceEditor(const char* id, std::string& text, const std::vector<int>& errorLines, SourceEditorState& state,
                  float height);

}  // namespace fraktal::editor
