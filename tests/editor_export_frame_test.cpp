// The export frame guide (app/editor/viewport/export_frame.hpp): every point of the guide in the viewport
// sees along the same ray as the matching point of the export, for exports narrower and wider
// than the viewport. No GL.
#include <gtest/gtest.h>

#include "app/editor/viewport/export_frame.hpp"
#include "core/camera.hpp"

namespace fraktal::editor {
namespace {

// The ray through a point given as shares (u, v) of an image's width and height from its top left.
vec3 rayAt(const Camera& c, double aspect, double u, double v) { return c.rayDirection(2 * u - 1, 1 - 2 * v, aspect); }

void expectGuideSeesTheExport(double viewAspect, double exportAspect) {
    SCOPED_TRACE("view " + std::to_string(viewAspect) + ", export " + std::to_string(exportAspect));
    Camera preset;
    preset.position = vec3(0.3, 1.2, 3.5);
    preset.fovY = 50.0;
    const ExportFrame f = exportFrameInView(viewAspect, exportAspect, preset.fovY);
    Camera view = preset;
    view.fovY = f.viewFovY;
    // The guide keeps the export's aspect on screen.
    EXPECT_NEAR((f.right - f.left) * viewAspect / (f.bottom - f.top), exportAspect, 1e-12);
    for (double u : {0.0, 0.25, 0.5, 0.9, 1.0})
        for (double v : {0.0, 0.4, 1.0}) {
            const vec3 exported = rayAt(preset, exportAspect, u, v);
            const vec3 shown = rayAt(view, viewAspect, f.left + u * (f.right - f.left), f.top + v * (f.bottom - f.top));
            EXPECT_NEAR(glm::length(exported - shown), 0.0, 1e-12) << "at " << u << ", " << v;
        }
}

TEST(ExportFrame, GuideShowsWhatTheExportShows) {
    expectGuideSeesTheExport(16.0 / 9.0, 1.0);       // narrower: a band of the full height
    expectGuideSeesTheExport(1.0, 2.0);              // wider: the viewport widens its view
    expectGuideSeesTheExport(1280.0 / 720.0, 2.0);   // wider, from a landscape viewport
    expectGuideSeesTheExport(4961.0 / 3508.0, 0.5);  // portrait export
}

TEST(ExportFrame, SameAspectIsTheWholeView) {
    const ExportFrame f = exportFrameInView(1.5, 1.5, 40.0);
    EXPECT_TRUE(f.wholeView());
    EXPECT_EQ(f.viewFovY, 40.0);
    EXPECT_FALSE(exportFrameInView(1.5, 1.0, 40.0).wholeView());
    EXPECT_FALSE(exportFrameInView(1.5, 2.0, 40.0).wholeView());
    EXPECT_GT(exportFrameInView(1.5, 2.0, 40.0).viewFovY, 40.0);
}

}  // namespace
}  // namespace fraktal::editor
