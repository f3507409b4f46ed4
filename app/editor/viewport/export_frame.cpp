#include "app/editor/viewport/export_frame.hpp"

#include <cmath>
#include <numbers>

namespace fraktal::editor {

ExportFrame exportFrameInView(double viewAspect, double exportAspect, double fovY) {
    ExportFrame f;
    f.viewFovY = fovY;
    if (!(viewAspect > 0.0) || !(exportAspect > 0.0)) return f;
    if (exportAspect <= viewAspect) {
        const double share = exportAspect / viewAspect;  // of the width, full height
        f.left = 0.5 - 0.5 * share;
        f.right = 0.5 + 0.5 * share;
        return f;
    }
    // Wider: the viewport's half-width tangent must be the export's, tan(fovY / 2) * exportAspect.
    const double degrees = 180.0 / std::numbers::pi;
    const double tanHalf = std::tan(0.5 * fovY / degrees);
    f.viewFovY = 2.0 * std::atan(tanHalf * exportAspect / viewAspect) * degrees;
    const double share = viewAspect / exportAspect;  // of the height, full width
    f.top = 0.5 - 0.5 * share;
    f.bottom = 0.5 + 0.5 * share;
    return f;
}

}  // namespace fraktal::editor
