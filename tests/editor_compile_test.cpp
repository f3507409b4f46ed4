// Structure edits compile in the background (app/editor/viewport/background_compiler.hpp): on a second
// context that shares objects with the viewport's, on another thread. While a structure compiles
// the view keeps its last image and says so; once it is ready the frames are the same as those
// of a view that compiles in place; a structure that does not compile leaves the last good image
// and reports the node.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/editor/viewport/background_compiler.hpp"
#include "app/editor/viewport/viewport_adapter.hpp"
#include "test_support.hpp"

namespace fraktal::editor {
namespace {

constexpr int kW = 48, kH = 32;

std::vector<uint8_t> readDisplay(const ViewportView& view) {
    std::vector<uint8_t> pixels(size_t(view.width()) * view.height() * 4);
    glGetTextureImage(view.displayTexture(), 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size()), pixels.data());
    return pixels;
}

// Renders frames until the compile finishes (at most a minute on llvmpipe); returns how many
// frames waited.
int renderUntilCompiled(ViewportView& view, const Preset& p, const ViewSettings& settings) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    int waited = 0;
    for (;;) {
        view.render(p, settings, kW, kH);
        if (!view.stats().compiling) return waited;
        ++waited;
        if (std::chrono::steady_clock::now() > deadline) return -1;
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
}

TEST(EditorCompile, StructureEditsCompileOnASharedContextInTheBackground) {
    gl::HeadlessContext& context = test::glContext();
    auto shared = context.createShared();
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    ViewSettings settings;
    settings.aaCap = 1;
    Preset preset = loadPreset(test::sourceDir() / "presets" / "menger.json");

    BackgroundCompiler compiler([&] { shared->bind(); }, [&] { shared->unbind(); });
    CoreViewportView background(color, &compiler);
    CoreViewportView inPlace(color);

    // The first structure: no image until the worker is done, then the same frames as in place.
    background.render(preset, settings, kW, kH);
    EXPECT_TRUE(background.stats().compiling) << "the first frame already had programs: nothing compiled aside";
    EXPECT_EQ(background.displayTexture(), 0u);
    ASSERT_GE(renderUntilCompiled(background, preset, settings), 0) << "the background compile never finished";
    inPlace.render(preset, settings, kW, kH);
    for (int f = 0; f < 40; ++f) {
        background.render(preset, settings, kW, kH);
        inPlace.render(preset, settings, kW, kH);
    }
    EXPECT_TRUE(background.compileError().empty()) << background.compileError();
    EXPECT_EQ(readDisplay(background), readDisplay(inPlace));
    EXPECT_EQ(background.stats().compiles, 1);

    // A structure edit: the last image stays on screen while the new structure compiles.
    const std::vector<uint8_t> before = readDisplay(background);
    Preset edited = preset;
    edited.formula.nodes.erase(edited.formula.nodes.begin());  // drop the abs fold
    ASSERT_NE(edited.formula.structureKey(), preset.formula.structureKey());
    background.render(edited, settings, kW, kH);
    if (background.stats().compiling) {
        EXPECT_EQ(readDisplay(background), before);
    }
    ASSERT_GE(renderUntilCompiled(background, edited, settings), 0);
    for (int f = 0; f < 40; ++f) {
        background.render(edited, settings, kW, kH);
        inPlace.render(edited, settings, kW, kH);
    }
    EXPECT_EQ(readDisplay(background), readDisplay(inPlace));
    EXPECT_EQ(background.stats().compiles, 2);

    // A custom block that does not compile: the error names it and the last good image stays.
    const std::vector<uint8_t> good = readDisplay(background);
    nlohmann::json j = presetToJson(edited);
    j["formula"]["customBlocks"] = nlohmann::json::array({{{"id", "broken_fold"},
                                                           {"category", "fold"},
                                                           {"help", "does not compile"},
                                                           {"glsl", "p.xyz = nope(p.xyz);\n"}}});
    j["formula"]["nodes"][0] = {{"block", "broken_fold"}};
    const Preset broken = parsePreset(j.dump(), "broken.json");
    ASSERT_GE(renderUntilCompiled(background, broken, settings), 0);
    EXPECT_NE(background.compileError().find("broken_fold"), std::string::npos) << background.compileError();
    for (int f = 0; f < 3; ++f) background.render(broken, settings, kW, kH);
    EXPECT_FALSE(background.stats().compiling) << "a failed structure is compiled again every frame";
    EXPECT_EQ(readDisplay(background), good);
}

// A grid made ahead on the worker for a size the viewport has left is still handed over, so that
// the caller frees it (about 90 MB at 690x520 on llvmpipe), and the newer request stands: the next
// grid handed over is of the newer size.
TEST(EditorCompile, AGridOfASizeAskedForBeforeIsHandedOverAndTheNewerRequestStands) {
    gl::HeadlessContext& context = test::glContext();
    auto shared = context.createShared();
    BackgroundCompiler compiler([&] { shared->bind(); }, [&] { shared->unbind(); });
    using GridSize = BackgroundCompiler::GridSize;
    const auto takeWithin = [&](std::chrono::seconds limit) {
        const auto deadline = std::chrono::steady_clock::now() + limit;
        for (;;) {
            if (std::unique_ptr<viewport::MarchState> grid = compiler.takeGrid()) return grid;
            if (std::chrono::steady_clock::now() > deadline) return std::unique_ptr<viewport::MarchState>();
            std::this_thread::sleep_for(std::chrono::milliseconds(2));
        }
    };
    const GridSize first{64, 40, 8}, second{96, 60, 8};
    EXPECT_EQ(compiler.takeGrid(), nullptr) << "a grid before any was asked for";
    compiler.requestGrid(first);
    std::unique_ptr<viewport::MarchState> made = takeWithin(std::chrono::seconds(30));
    ASSERT_NE(made, nullptr) << "the worker made no grid";
    EXPECT_EQ((GridSize{made->width(), made->height(), made->coneTile()}), first);

    // The window changes size while a grid is made (a large one, under way after a few
    // milliseconds): every grid made comes out, the old size's for its taker to free, and the
    // newer size's follows.
    const GridSize large{1024, 768, 8};
    compiler.requestGrid(large);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    compiler.requestGrid(second);
    std::vector<GridSize> handed;
    while (std::unique_ptr<viewport::MarchState> grid = takeWithin(std::chrono::seconds(30))) {
        handed.push_back({grid->width(), grid->height(), grid->coneTile()});
        if (handed.back() == second) break;
    }
    ASSERT_FALSE(handed.empty()) << "no grid after the resize";
    EXPECT_EQ(handed.back(), second) << "the newer request was dropped with the older grid";
    for (const GridSize& g : handed) EXPECT_TRUE(g == large || g == second) << g.width << "x" << g.height;
    std::printf("grids handed over after the resize: %zu (the old size's made first: %s)\n", handed.size(),
                handed.front() == large ? "yes" : "no");
}

}  // namespace
}  // namespace fraktal::editor
