// A value typed into a slider (Ctrl+click or double-click, then the keys) that lies outside the
// slider's range is brought into it. The artist is told so, naming the slider, what they typed
// and what it became, instead of seeing the number change under their hands. The sliders
// (param_widgets.hpp: dragClamped) clamp and track the typing here; the editor shows the notice
// on its status line. No ImGui in this file: the rules are unit-tested.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace fraktal::editor {

struct ClampNotice {
    std::string param;     // the slider's label
    double typed = 0.0;    // what was typed (for a vector, the first component outside the range)
    double clamped = 0.0;  // what it became: the nearer end of the range
    double lo = 0.0, hi = 0.0;
    bool integer = false;  // an integer slider: the numbers are shown without decimals
    bool operator==(const ClampNotice&) const = default;
};

// Clamps each of `values` into [lo, hi]. The notice names the first value that was outside;
// none when all were inside, or when lo > hi (a range that is no range: ImGui leaves such a
// slider unclamped too).
std::optional<ClampNotice> clampIntoRange(std::string_view param, std::span<double> values, double lo, double hi,
                                          bool integer = false);

// "Bound radius: 0 is outside 0.01 .. 100, set to 0.01".
std::string clampMessage(const ClampNotice& notice);

// The slider's text as its label shows it: the part before "##" (ImGui's hidden ID suffix).
std::string_view visibleLabel(std::string_view label);

// The typing into one slider, frame by frame. While the artist types, every keystroke's value
// is applied (and clamped) at once; the notice waits until they leave the field (Enter, Tab, a
// click elsewhere), so that it names the number they ended with: typing "100" into a 0 .. 10
// slider is reported once, as 100, and "0.5" typed over a clamped "-" reports nothing. Only one
// slider is typed into at a time; `id` tells them apart.
class ClampReports {
   public:
    // After slider `id` was drawn this frame: `notice` from clamping what it changed (none when
    // that was inside the range, or nothing changed); `left` whether the artist left it this frame.
    void drawn(unsigned id, std::optional<ClampNotice> notice, bool changed, bool left);
    // The notice of a slider the artist has left since the last call, once.
    std::optional<ClampNotice> take();

   private:
    unsigned pendingId_ = 0;
    std::optional<ClampNotice> pending_;  // the last clamp of slider pendingId_ while it is typed into
    std::optional<ClampNotice> ready_;
};

}  // namespace fraktal::editor
