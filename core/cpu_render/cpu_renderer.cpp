#include "core/cpu_render/cpu_renderer.hpp"

#include <atomic>
#include <cmath>
#include <thread>
#include <vector>

#include "core/cpu_render/cpu_shading.hpp"

namespace fraktal {

ImageStrip renderReference(const Formula& formula, const Camera& camera, const RenderSettings& render,
                           const ShadingParams& shading, int threads) {
    ImageStrip image;
    image.resize(render.width, 0, render.height);
    const cpu::Scene scene{formula, shading};
    const double aspect = double(render.width) / double(render.height);
    const double pixelAngle = camera.pixelAngle(render.height, render.width);

    auto renderPixel = [&](int x, int y) {
        const size_t i = (size_t(y) * size_t(render.width) + size_t(x)) * 4;
        const double ndcX = 2.0 * (x + 0.5) / render.width - 1.0;
        const double ndcY = 1.0 - 2.0 * (y + 0.5) / render.height;
        const vec3 rd = camera.rayDirection(ndcX, ndcY, aspect);
        const vec3 ro = camera.position;
        double deEvals = 0.0, tStart, tEnd;
        bool hit = false;
        cpu::MarchState s = cpu::marchStart(scene, 0.0);
        if (cpu::clipCameraRay(scene, ro, rd, tStart, tEnd)) {
            s = cpu::marchStart(scene, tStart);
            cpu::marchRay(scene, ro, rd, tEnd, pixelAngle, render.maxSteps, s, deEvals);
            hit = cpu::countsAsHit(scene, s, pixelAngle);
        }
        vec3 color = render.transparentBackground ? vec3(0.0) : cpu::shadeBackground(scene, rd);
        float depth = 1e30f;
        if (hit) {
            const cpu::SurfaceSample surface = cpu::shadeSurface(scene, ro + rd * s.t, rd, s.t, pixelAngle, deEvals);
            color = surface.color;
            depth = float(s.t);
            for (int c = 0; c < 3; ++c) {
                image.normalDepth[i + c] = float(surface.normal[c]);
                image.albedoAO[i + c] = float(surface.albedo[c]);
            }
            image.albedoAO[i + 3] = float(surface.ao);
        }
        for (int c = 0; c < 3; ++c) image.rgba[i + c] = float(color[c]);
        image.rgba[i + 3] = hit ? 1.0f : 0.0f;
        image.normalDepth[i + 3] = depth;
        image.stats[i] = float(deEvals);
        image.stats[i + 1] = float(s.steps);
    };

    std::atomic<int> nextRow{0};
    auto worker = [&] {
        for (int y = nextRow++; y < render.height; y = nextRow++)
            for (int x = 0; x < render.width; ++x) renderPixel(x, y);
    };
    const int n = threads > 0 ? threads : int(std::max(1u, std::thread::hardware_concurrency()));
    std::vector<std::thread> pool;
    for (int t = 1; t < n; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    return image;
}

}  // namespace fraktal
