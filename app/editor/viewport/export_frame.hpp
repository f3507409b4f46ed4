// The export frame in the viewport: the region of the viewport an export of another aspect ratio
// shows. An export renders the preset's camera at the export size, its vertical field of view as
// the preset says. When the export is narrower than the viewport that is a centred band of the
// viewport's full height; when it is wider, the viewport widens its own vertical field of view so
// that the export's full width fits, and the export is a centred band of the viewport's full
// width. The guide is drawn over the viewport; the export shows exactly what lies inside it.
// Pure logic (tests/editor_logic_test.cpp).
#pragma once

namespace fraktal::editor {

struct ExportFrame {
    // The guide, as shares of the viewport's width and height from its top-left corner.
    double left = 0.0, top = 0.0, right = 1.0, bottom = 1.0;
    double viewFovY = 0.0;  // the vertical field of view (degrees) the viewport renders with
    bool wholeView() const { return left <= 0.0 && top <= 0.0 && right >= 1.0 && bottom >= 1.0; }
};

// viewAspect, exportAspect: width / height; fovY: the preset camera's, in degrees.
ExportFrame exportFrameInView(double viewAspect, double exportAspect, double fovY);

}  // namespace fraktal::editor
