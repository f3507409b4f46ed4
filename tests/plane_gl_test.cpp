// 2D fractals through GL: GPU and CPU agree on every pixel's classification except at a thin
// boundary band; deep zooms keep their structure in fp64; the editor's view refines; the CLI
// renders a 2D preset to EXR (with AOVs) and PNG.
#include <ImfChannelList.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>

#include <set>

#include "core/plane/plane_glsl.hpp"
#include "core/plane/plane_renderer.hpp"
#include "core/plane/plane_view.hpp"
#include "tests/test_support.hpp"
#include "tests/uniform_lookups.hpp"

namespace fraktal {
namespace {

namespace fs = std::filesystem;

PlanePreset shipped2d(const std::string& name) { return loadPlanePreset(test::sourceDir() / "presets/2d" / name); }

PlaneTileData renderView(const PlanePreset& p, const PlaneViewRect& view, int w, int h, int spp,
                         PlanePrecision precision = PlanePrecision::Auto) {
    test::glContext();
    PlaneRenderer renderer;
    renderer.prepare(p.formula, precision);
    PlaneTarget target;
    renderer.render(p.formula, p.colouring, view, PlaneTile{w, h, 0, 0, w, h}, target, 0, spp, false);
    return readPlaneTarget(target);
}

class PlaneAgreement : public ::testing::TestWithParam<std::string> {};

// One sample per pixel at its centre: the GPU's inside/outside against evaluatePlane at the very
// same position. Pixels whose 3x3 CPU neighbourhood is mixed form the boundary band, where fused
// multiply-adds or the float smooth count may tip a point either way; everywhere else they must
// agree exactly.
TEST_P(PlaneAgreement, GpuAndCpuClassifyEveryPixelAlikeOutsideTheBoundaryBand) {
    PlanePreset p = shipped2d(GetParam());
    // Agreement holds at any depth; a shallow one keeps enough of the Sierpinski triangle's
    // (3/4)^n area on screen for the check to see the set. Escape-time sets are compared at up
    // to 50 iterations: deeper, a Julia orbit's escape iteration can flip under the GPU's fused
    // multiply-adds away from the one-pixel band (18 of 6506 pixels at the preset's 500).
    p.formula.iterations = std::min(p.formula.iterations, GetParam() == "sierpinski_triangle.json" ? 6 : 50);
    const int w = 96, h = 72;
    const PlaneTileData gpu = renderView(p, p.view, w, h, 1);
    std::vector<int> cpu(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            cpu[size_t(y) * w + x] =
                evaluatePlane(p.formula, planePixelPosition(p.view, w, h, x, y, planeSampleOffset(0))).inside;
    int band = 0, compared = 0, mismatches = 0, insideCount = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int c = cpu[size_t(y) * w + x];
            insideCount += c;
            bool mixed = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, h - 1);
                    mixed |= cpu[size_t(ny) * w + nx] != c;
                }
            if (mixed) {
                ++band;
                continue;
            }
            ++compared;
            const double g = gpu.insideFraction(x, y);
            ASSERT_TRUE(g == 0.0 || g == 1.0) << "one sample per pixel";
            if (int(g) != c) ++mismatches;
        }
    EXPECT_EQ(mismatches, 0) << GetParam() << ": " << mismatches << " of " << compared << " pixels disagree";
    EXPECT_GT(insideCount, w * h / 50) << "the test view must show the set";
    EXPECT_LT(insideCount, w * h - w * h / 50) << "and its outside";
    EXPECT_LT(band, w * h * 2 / 5) << "the boundary band must stay thin";
}

INSTANTIATE_TEST_SUITE_P(Shipped, PlaneAgreement,
                         ::testing::Values("sierpinski_triangle.json", "koch_snowflake.json", "mandelbrot.json",
                                           "julia.json", "multibrot.json"),
                         [](const auto& info) { return info.param.substr(0, info.param.find('.')); });

// Fraction of pixels whose smooth iteration count differs from the neighbour (dx, dy) away.
double structure(const PlaneTileData& d, int dx, int dy) {
    int differ = 0, pairs = 0;
    for (int y = 0; y + dy < d.height; ++y)
        for (int x = 0; x + dx < d.width; ++x, ++pairs)
            differ += d.meanIterations(x, y) != d.meanIterations(x + dx, y + dy);
    return double(differ) / pairs;
}

// c = i is a Misiurewicz point on the boundary: the set has structure about it at every scale.
// At a view width of 1e-12 neighbouring pixels are 1.6e-14 apart, far below float's 6e-8 at |c| =
// 1: in float every row collapses onto y = 1 (x, near 0, keeps its precision, so the float image
// is made of vertical stripes); in double every pixel differs from its neighbours.
TEST(PlaneDeepZoom, StructureSurvivesAtViewWidth1e12WithFp64) {
    test::glContext();
    ASSERT_TRUE(planeFp64Available()) << "llvmpipe has fp64 (GL 4.5)";
    PlanePreset p = shipped2d("mandelbrot.json");
    const PlaneViewRect deep{real2(0.0, 1.0), 1e-12};
    const PlaneTileData fp64 = renderView(p, deep, 64, 64, 1, PlanePrecision::Double);
    const PlaneTileData fp32 = renderView(p, deep, 64, 64, 1, PlanePrecision::Float);
    EXPECT_GT(structure(fp64, 1, 0), 0.5);
    EXPECT_GT(structure(fp64, 0, 1), 0.5);
    EXPECT_LT(structure(fp32, 0, 1), 0.05) << "float must be blocky here, else this test proves nothing";
    // And the fp64 image is the CPU's: the same escape counts at sample pixels.
    for (int y = 0; y < 64; y += 9)
        for (int x = 0; x < 64; x += 7) {
            const PlaneEvaluation e =
                evaluatePlane(p.formula, planePixelPosition(deep, 64, 64, x, y, planeSampleOffset(0)));
            if (!e.inside) {
                EXPECT_NEAR(fp64.meanIterations(x, y), e.smoothIterations, 0.05) << x << "," << y;
            }
        }
}

TEST(PlaneDeepZoom, NonWholePowerWarnsAboutFloat) {
    test::glContext();
    PlanePreset p = shipped2d("multibrot.json");
    p.formula.nodes[0].values[0].x = 2.5;
    PlaneRenderer renderer;
    renderer.prepare(p.formula);
    ASSERT_EQ(renderer.warnings().size(), 1u);
    EXPECT_NE(renderer.warnings()[0].find("non-whole power"), std::string::npos);
    p.formula.nodes[0].values[0].x = 3.0;
    renderer.prepare(p.formula);
    EXPECT_TRUE(renderer.warnings().empty());
}

TEST(PlaneSupersampling, BoundaryPixelsArePartlyInsideAndTheMeanMatchesTheCpu) {
    const PlanePreset p = shipped2d("mandelbrot.json");
    const int w = 48, h = 36, spp = 16;
    const PlaneTileData d = renderView(p, p.view, w, h, spp);
    int partial = 0;
    double gpuArea = 0.0, cpuArea = 0.0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            EXPECT_EQ(d.samples(x, y), spp);
            const double f = d.insideFraction(x, y);
            partial += f > 0.0 && f < 1.0;
            gpuArea += f;
            for (int k = 0; k < spp; ++k)
                cpuArea +=
                    evaluatePlane(p.formula, planePixelPosition(p.view, w, h, x, y, planeSampleOffset(k))).inside;
        }
    EXPECT_GT(partial, 20);
    EXPECT_NEAR(gpuArea, cpuArea / spp, 0.5);
}

TEST(PlaneViewLogic, ZoomKeepsThePointUnderTheCursorAndPanFollowsIt) {
    const PlaneViewRect v{real2(-0.5, 0.1), 3.0};
    const int w = 200, h = 100;
    const double cx = 37.25, cy = 81.5;
    const real2 before = planePixelPosition(v, w, h, 0, 0, glm::vec2(0.0f)) + real2(cx, -cy) * v.pixelSize(w);
    const PlaneViewRect z = planeZoomedAt(v, w, h, cx, cy, 8.0);
    const real2 after = planePixelPosition(z, w, h, 0, 0, glm::vec2(0.0f)) + real2(cx, -cy) * z.pixelSize(w);
    EXPECT_NEAR(glm::length(after - before), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(z.width, 3.0 / 8.0);
    // Dragging by (10, 5) pixels moves the point that was at a pixel to 10 right, 5 down.
    const PlaneViewRect p = planePanned(v, w, 10.0, 5.0);
    EXPECT_NEAR(glm::length(planePixelPosition(p, w, h, 20, 30, glm::vec2(0.5f)) -
                            planePixelPosition(v, w, h, 10, 25, glm::vec2(0.5f))),
                0.0, 1e-12);
}

TEST(PlaneViewLogic, RefinementStartsWithOneSampleAndReachesTheTarget) {
    PlaneRefinement r;
    r.target = 20;
    std::vector<int> passes;
    while (!r.finished()) {
        passes.push_back(r.nextPassSamples());
        r.samplesDone += passes.back();
    }
    EXPECT_EQ(passes.front(), 1);
    EXPECT_EQ(r.samplesDone, 20);
    for (int n : passes) EXPECT_LE(n, r.maxPerPass);
    EXPECT_EQ(r.nextPassSamples(), 0);
}

// The editor sizes passes to a time budget: as many samples as fit (by the last pass's cost per
// sample), never none, never past the cap; unmeasured, the cap.
TEST(PlaneViewLogic, PassSamplesFitTheTimeBudget) {
    EXPECT_EQ(planeSamplesForBudget(0.0, 60.0, 8), 8);
    EXPECT_EQ(planeSamplesForBudget(20.0, 60.0, 8), 3);
    EXPECT_EQ(planeSamplesForBudget(125.0, 60.0, 8), 1) << "a slow sample still makes progress";
    EXPECT_EQ(planeSamplesForBudget(0.5, 60.0, 8), 8);
    PlaneRefinement r;
    r.samplesDone = 4;
    r.maxPerPass = planeSamplesForBudget(30.0, 60.0, 8);
    EXPECT_EQ(r.nextPassSamples(), 2);
}

// While the view moves, the editor renders at the size where one sample takes the budget.
TEST(PlaneViewLogic, InteractiveScaleFitsOneSampleInTheBudget) {
    EXPECT_EQ(planeInteractiveScale(0.0, 800, 600, 60.0), 1.0) << "not measured yet: full size";
    EXPECT_EQ(planeInteractiveScale(1e-5, 800, 600, 60.0), 1.0) << "4.8 ms a sample fits";
    const double perPixel = 2e-3;  // 960 ms for a sample of 800x600
    const double s = planeInteractiveScale(perPixel, 800, 600, 60.0);
    EXPECT_NEAR(perPixel * (800 * s) * (600 * s), 60.0, 1e-9);
    EXPECT_EQ(planeInteractiveScale(1.0, 800, 600, 60.0), 0.25) << "never below the minimum";
}

// A pass rendered in bands over several calls (the editor's time budget) gives exactly the
// image of whole passes, and counts its samples only once the last band is done.
TEST(PlaneViewGl, PassesInBandsGiveTheSameImage) {
    test::glContext();
    const PlanePreset preset = loadPlanePreset(test::sourceDir() / "presets" / "2d" / "mandelbrot.json");
    const int w = 24, h = 17;
    auto image = [&](PlaneView& v) {
        std::vector<float> pixels(size_t(w) * h * 4);
        glGetTextureImage(v.colourTexture(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * sizeof(float)),
                          pixels.data());
        return pixels;
    };
    PlaneView whole, banded;
    for (PlaneView* v : {&whole, &banded}) {
        v->setPreset(preset);
        v->refinement().target = 7;
    }
    while (whole.refining()) ASSERT_TRUE(whole.update(w, h));
    int calls = 0;
    while (banded.refining()) {
        const int before = banded.samples();
        ASSERT_TRUE(banded.update(w, h, 5));
        EXPECT_LE(banded.lastPixelSamples(), 5.0 * w * 8) << "at most 5 rows of one pass";
        if (++calls % 4 != 0) {
            EXPECT_EQ(banded.samples(), before) << "17 rows take 4 bands of 5";
        }
        ASSERT_LT(calls, 100);
    }
    EXPECT_EQ(banded.samples(), 7);
    EXPECT_GT(calls, 4);
    const std::vector<float> a = image(whole), b = image(banded);
    EXPECT_EQ(a, b);
    float alphaMin = 1e9f;
    for (size_t i = 3; i < b.size(); i += 4) alphaMin = std::min(alphaMin, b[i]);
    EXPECT_EQ(alphaMin, 7.0f) << "every pixel holds all its samples";
}

// The 2D renderer finds its uniforms' locations when it builds the program: passes of the same
// formula, in bands or whole, after a zoom or with new values, look none up.
TEST(PlaneViewGl, PassesLookUpNoUniformLocations) {
    test::glContext();
    PlaneView view;
    PlanePreset preset = shipped2d("julia.json");
    view.setPreset(preset);
    view.refinement().target = 4;
    ASSERT_TRUE(view.update(24, 16));  // builds the program
    const test::UniformLookups counter;
    while (view.update(24, 16, 5)) {
    }
    view.zoomAt(12, 8, 2.0);
    EXPECT_TRUE(view.update(24, 16));
    EXPECT_EQ(test::UniformLookups::calls, 0);
}

TEST(PlaneViewGl, RefinesWhileStillAndRestartsOnZoom) {
    test::glContext();
    PlaneView view;
    view.setPreset(shipped2d("julia.json"));
    view.refinement().target = 6;
    int passes = 0;
    while (view.update(24, 16)) ++passes;
    EXPECT_EQ(view.samples(), 6);
    EXPECT_GE(passes, 3);
    std::vector<float> pixels(24 * 16 * 4);
    glGetTextureImage(view.colourTexture(), 0, GL_RGBA, GL_FLOAT, GLsizei(pixels.size() * 4), pixels.data());
    for (size_t i = 3; i < pixels.size(); i += 4) ASSERT_EQ(pixels[i], 6.0f) << "every pixel holds every sample";
    view.zoomAt(12, 8, 2.0);
    EXPECT_TRUE(view.refining());
    EXPECT_EQ(view.samples(), 0);
    EXPECT_TRUE(view.update(24, 16));
    EXPECT_EQ(view.samples(), 1);
}

TEST(PlaneCli, RendersA2dPresetToExrWithAovsAndPng) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_plane_cli_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path exr = dir / "m.exr", png = dir / "m.png";
    const auto run = test::runCli("render " + (test::sourceDir() / "presets/2d/mandelbrot.json").string() + " -o " +
                                  exr.string() + " --png " + png.string() + " --size 40x30 --spp 4 -q");
    ASSERT_EQ(run.exitCode, 0) << run.output;
    ASSERT_TRUE(fs::exists(exr));
    ASSERT_TRUE(fs::exists(png));
    Imf::InputFile in(exr.c_str());
    const Imf::ChannelList& channels = in.header().channels();
    for (const char* name : {"R", "G", "B", "A", "inside", "iterations", "distance"})
        EXPECT_NE(channels.findChannel(name), nullptr) << name;
    EXPECT_EQ(in.header().dataWindow().max.x, 39);
    EXPECT_EQ(in.header().dataWindow().max.y, 29);
    // Bad input: a clear error, non-zero exit, no file.
    const auto bad = test::runCli("render " + (test::sourceDir() / "presets/2d/mandelbrot.json").string() + " -o " +
                                  (dir / "x.exr").string() + " --view NoSuchView -q");
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_NE(bad.output.find("NoSuchView"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(dir / "x.exr"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace fraktal
