// The Colouring tab of a 2D document: the preset's "colouring" section
// (core/plane/plane_colouring.hpp), which the 2D view and the still export both read. Colours
// are linear Rec.709 as the preset stores them.
#include <imgui.h>

#include "app/editor/panels/panels.hpp"
#include "app/editor/widgets/param_widgets.hpp"
#include "app/editor/widgets/setting_widgets.hpp"

namespace fraktal::editor {

void drawPlaneColouringTab(EditorState& s) {
    if (!s.doc.plane) return;
    PlaneColouring& c = s.doc.plane->colouring;
    ImGui::PushItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
    sectionHeader("Outside: smooth iteration count");
    paletteChoice(c.paletteA, c.paletteB, c.paletteC, c.paletteD);
    helpMarker(
        "colour = a + b cos(2 pi (c t + d)), t = frequency * smooth iteration count + offset (the normalised "
        "iteration count: no bands with a large bailout).");
    dragDouble("Frequency", c.frequency, -1e3, 1e3, 0.0005f, "%.4f", "Palette cycles per iteration.");
    dragDouble("Offset", c.offset, -1e3, 1e3, 0.002f, "%.3f", "Shifts the palette along t.");
    paletteTerms(c.paletteA, c.paletteB, c.paletteC, c.paletteD);
    sectionHeader("Inside and edges");
    colorEdit("Inside", c.interior, "Colour of points in the set (linear Rec.709).");
    dragDouble("Edge width", c.edgeWidth, 0.0, 100.0, 0.01f, "%.2f px",
               "Distance-estimate shading: outside points closer than this many pixels darken toward the "
               "boundary, which keeps thin filaments visible (0: off).");
    ImGui::PopItemWidth();
    ImGui::Spacing();
    if (ImGui::Button("Reset colouring to defaults")) c = PlaneColouring{};
}

}  // namespace fraktal::editor
