#include "app/editor/widgets/node_list_widgets.hpp"

namespace fraktal::editor {

void errorUnder(const std::string& error) {
    ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(error.c_str());
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

}  // namespace fraktal::editor
