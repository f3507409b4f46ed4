#include "app/editor/widgets/node_list_widgets.hpp"

namespace fraktal::editor {

namespace {
// 1st, 2nd, 3rd, 4th, ..., 11th, 12th, 13th, ..., 21st.
std::string ordinal(int n) {
    const int tens = n % 100, ones = n % 10;
    const char* suffix = tens >= 11 && tens <= 13 ? "th"
                         : ones == 1              ? "st"
                         : ones == 2              ? "nd"
                         : ones == 3              ? "rd"
                                                  : "th";
    return std::to_string(n) + suffix;
}
}  // namespace

std::string scheduleText(const IterationSchedule& s) {
    std::string text;
    if (s.period > 1) text = "every " + ordinal(s.period) + " iteration from the " + ordinal(s.phase + 1);
    if (s.windowed())
        text += (text.empty() ? "" : ", ") + std::string("iterations ") + std::to_string(s.start + 1) +
                (s.stop < kMaxIterations ? " to " + std::to_string(s.stop) : std::string(" on"));
    return text;
}

void errorUnder(const std::string& error) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(error.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

}  // namespace fraktal::editor
