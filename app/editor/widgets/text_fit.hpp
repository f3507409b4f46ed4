// Text the editor draws where it does not fit: a label that runs past its window's right edge, a
// line of text or a row of widgets wider than its window, a table cell's text cut at the cell's
// edge, a combo's choice wider than its box. ImGui clips all of them silently; the state file
// lists them so that the Xvfb tests can hold every panel, dialog and help window to its size.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace fraktal::editor {

struct ClippedText {
    std::string window;  // the ImGui window it is drawn in (its name as ImGui knows it)
    std::string text;    // the label or choice that is cut, or what sticks out when unnamed
    float hidden = 0;    // how many pixels of it do not show
};

// Call right after a combo (ImGui::Combo or BeginCombo, closed) whose box shows `choice`: records
// the choice when it is wider than the box, which cuts it without a sign.
void checkComboFits(std::string_view label, std::string_view choice);

// Call right after a labelled item: records its label when the item ends past the visible right
// edge of its window (or table cell).
void checkItemFits(std::string_view label);

// Everything cut this frame: the items recorded above, then every window and table cell whose
// content runs past its visible right edge. Call after the frame's windows have ended, before the
// next frame begins.
std::vector<ClippedText> clippedText();

}  // namespace fraktal::editor
