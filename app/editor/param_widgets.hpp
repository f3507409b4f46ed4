// Widgets generated from a block's parameter declaration (core/block.hpp ParamDecl): a drag
// with the declared range (Ctrl+click or double-click to type a value), the help text as a
// tooltip, and a reset-to-default button. One declaration, so every block gets the same UI.
#pragma once

#include "core/block.hpp"

namespace fraktal::editor {

// Draws the widget for one parameter; returns whether the value changed this frame. The value
// is clamped to the declared range.
bool paramWidget(const ParamDecl& decl, ParamValue& value);

// A "(?)" marker whose tooltip shows `help` (used beside headers and settings).
void helpMarker(const char* help);

// A titled separator (ImGui 1.86 has no SeparatorText).
void sectionHeader(const char* title);

}  // namespace fraktal::editor
