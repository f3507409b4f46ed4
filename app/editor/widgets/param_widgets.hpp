// Widgets generated from a block's parameter declaration (core/block.hpp ParamDecl): a drag
// with the declared range (Ctrl+click or double-click to type a value), or a checkbox for an
// on/off parameter, the help text as a tooltip, and a reset-to-default button. One declaration,
// so every block gets the same UI.
#pragma once

#include <string>
#include <vector>

#include "core/block.hpp"

namespace fraktal::editor {

// What the parameter widgets showed in one frame, for the state file that tests driving the
// editor read: where each parameter's control is and the help of the tooltip shown. The
// editor clears it before drawing a frame; the widgets fill it.
struct ParamWidgetsShown {
    struct Widget {
        std::string name;
        float x = 0, y = 0, w = 0, h = 0;  // the drag or checkbox, in window coordinates
    };
    std::vector<Widget> widgets;
    std::string tooltipParam;  // the parameter whose tooltip is shown (empty: none)
    std::string tooltip;       // its declaration's help text, as the tooltip shows it
    void clear() { *this = {}; }
    // Records the last ImGui item as `name`.
    void noteLastItem(std::string name);
};

// Draws the widget for one parameter; returns whether the value changed this frame. The value
// is clamped to the declared range; a toggle is 0 or 1. `shown`, when given, records it.
bool paramWidget(const ParamDecl& decl, ParamValue& value, ParamWidgetsShown* shown = nullptr);

// A "(?)" marker whose tooltip shows `help` (used beside headers and settings).
void helpMarker(const char* help);

// A titled separator (ImGui 1.86 has no SeparatorText).
void sectionHeader(const char* title);

}  // namespace fraktal::editor
