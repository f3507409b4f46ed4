#include "core/viewport/warm_up.hpp"

#include <stdexcept>

#include "core/viewport/viewport.hpp"

namespace fraktal::viewport {

std::unique_ptr<ViewportPrograms> warmUp(std::unique_ptr<ViewportPrograms> programs, const Formula& formula,
                                         WarmUpFrames frames) {
    // llvmpipe's machine code is also keyed by whether each bound image's sides are powers of two.
    // The real grids (a window's viewport and its scaled copies under motion, the 272x170
    // thumbnails) almost never are, so neither are these: 24 and 20 pixels, their cone images
    // (tile 8: 3x3) and their reprojection targets (3 rows per row: 72 and 60). A move from rest
    // onto a grid a quarter the side (6 pixels) scatters blocks of points (reprojectBlock), as the
    // editor's first frame of motion after rest does.
    constexpr int kRest = 24, kMoving = 20, kMovingSmall = 6;
    static_assert(kRest / kMovingSmall >= 4, "reprojectBlock gives blocks from a ratio of 4");
    const bool motion = frames == WarmUpFrames::StillAndMotion;
    ViewportOptions options;
    options.coneTile = motion ? 8 : 0;  // the editor's cone pre-pass is an option of its own (off by default)
    Viewport v(options);
    v.adoptPrograms(std::move(programs));
    try {
        RenderSettings render;
        render.maxSteps = 16;
        const ShadingSettings shading;
        Camera camera;
        v.render(formula, camera, render, shading, kRest, kRest);  // reset: march from the start, shade
        v.render(formula, camera, render, shading, kRest, kRest);  // at rest: march on, accumulate
        if (motion) {
            camera.position.x += 0.1;
            v.render(formula, camera, render, shading, kMoving, kMoving);  // reprojected onto a smaller grid
            camera.position.x += 0.1;
            v.render(formula, camera, render, shading, kMoving, kMoving);  // reprojected, the list march
        }
        options.slices = 2;
        v.setOptions(options);
        v.render(formula, camera, render, shading, kRest, kRest);  // sliced (back to the larger grid)
        v.render(formula, camera, render, shading, kRest, kRest);
        if (motion) {
            camera.position.x += 0.1;
            v.render(formula, camera, render, shading, kMovingSmall, kMovingSmall);  // blocks of points
        }
    } catch (const std::exception&) {
        // The programs linked; only the early translation is lost.
    }
    return v.releasePrograms();
}

}  // namespace fraktal::viewport
