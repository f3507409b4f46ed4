// Widgets generated from a block's parameter declaration (core/block.hpp ParamDecl): a drag
// with the declared range (Ctrl+click or double-click to type a value), or a checkbox for an
// on/off parameter, the help text as a tooltip, and a reset-to-default button. One declaration,
// so every block gets the same UI.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "app/editor/widgets/value_clamp.hpp"
#include "core/block.hpp"
#include "core/param_label.hpp"  // the name a parameter's widget shows

namespace fraktal::editor {

// What the parameter widgets showed in one frame, for the state file that tests driving the
// editor read: where each parameter's control is and the help of the tooltip shown. The
// editor clears it before drawing a frame; the widgets fill it.
struct ParamWidgetsShown {
    struct Widget {
        std::string name;                  // the parameter's name in presets
        std::string label;                 // what the widget shows (paramLabel)
        float x = 0, y = 0, w = 0, h = 0;  // the drag or checkbox, in window coordinates
    };
    std::vector<Widget> widgets;
    // The group headings above the parameters, in order (an imported frag's #group), each with
    // the index in `widgets` of the first parameter under it.
    std::vector<std::pair<std::string, size_t>> groups;
    std::string tooltipParam;  // the parameter whose tooltip is shown (empty: none)
    std::string tooltip;       // its declaration's help text, as the tooltip shows it
    void clear() { *this = {}; }
    // Records the last ImGui item as parameter `name` showing `label` (empty: the name).
    void noteLastItem(std::string name, std::string label = {});
};

// Draws the widget for one parameter; returns whether the value changed this frame. The value
// is clamped to the declared range (a typed value outside it is reported: dragClamped); a toggle
// is 0 or 1. `shown`, when given, records it.
bool paramWidget(const ParamDecl& decl, ParamValue& value, ParamWidgetsShown* shown = nullptr);

// While one is alive, the sliders below send what they clamp to `reports`: the editor opens one
// around each frame's panels. (ImGui keeps one context per program; so does this.)
class ReportClamps {
   public:
    explicit ReportClamps(ClampReports& reports);
    ~ReportClamps();
    ReportClamps(const ReportClamps&) = delete;
    ReportClamps& operator=(const ReportClamps&) = delete;

   private:
    ClampReports* previous_;
};

// ImGui's drag of `count` (1 to 4) doubles or ints over [lo, hi] that clamps a typed value
// itself and reports it under `name` (by default the label's visible text): with
// ImGuiSliderFlags_AlwaysClamp ImGui would clamp it silently. `flags` are ImGuiSliderFlags; a drag
// with the mouse stays within the range as before. Every slider of the editor with a range is one.
bool dragClamped(const char* label, double* values, int count, float speed, double lo, double hi, const char* format,
                 int flags = 0, std::string_view name = {});
bool dragClamped(const char* label, int* values, int count, float speed, int lo, int hi, const char* format,
                 int flags = 0, std::string_view name = {});

// ImGui's input box for one int (with +/- buttons when `step` > 0) or one double over [lo, hi]
// that clamps and reports a typed value as dragClamped does (the schedule's and the timeline's
// number fields).
bool inputClamped(const char* label, int* value, int step, int stepFast, int lo, int hi, std::string_view name = {});
bool inputClamped(const char* label, double* value, double lo, double hi, const char* format,
                  std::string_view name = {});

// A "(?)" marker whose tooltip shows `help` (used beside headers and settings).
void helpMarker(const char* help);

// A titled separator (ImGui 1.86 has no SeparatorText).
void sectionHeader(const char* title);

}  // namespace fraktal::editor
