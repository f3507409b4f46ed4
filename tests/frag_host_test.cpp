// The frag bench's host (bench/frag/frag_host.cpp: a frag's own raytracer GLSL run as written) on
// the tests' own frags, against fraktal's import of each: every frag of tests/data/frag_import that
// imports draws the silhouette its own raytracer draws (IoU >= 0.9 of the hit masks at 160x120, the
// bench's measure), with tests/data/frag_host's raytracer and 3D setup in FragM's dialect standing
// in for FragM's. The library's frags are not the project's to ship; bench/frag/README.md runs them.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "bench/import/silhouette.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

const std::string kSize = "160x120";

std::string shellQuoted(const std::filesystem::path& p) { return "'" + p.string() + "'"; }

// The host's line for `frag`: "KIND ok HITS DE_PER_PIXEL" or "KIND fail REASON".
test::CliRun runHost(const std::filesystem::path& frag, const std::string& mask) {
    return test::runShell(std::string(FRAKTAL_FRAG_HOST) + " " + shellQuoted(frag) + " --include-dir " +
                          shellQuoted(test::sourceDir() / "tests/data/frag_host") + " --size " + kSize + " -o " +
                          shellQuoted(mask) + " 2>/dev/null");
}

}  // namespace

TEST(FragHost, EveryImportingTestFragDrawsWhatItsOwnRaytracerDraws) {
    const test::Sandbox box("fraktal_frag_host_");
    std::vector<std::filesystem::path> frags;
    for (const auto& entry : std::filesystem::directory_iterator(test::sourceDir() / "tests/data/frag_import"))
        if (entry.path().extension() == ".frag") frags.push_back(entry.path());
    std::sort(frags.begin(), frags.end());
    int compared = 0;
    for (const std::filesystem::path& frag : frags) {
        SCOPED_TRACE(frag.filename().string());
        const std::string stem = frag.stem().string(), json = box.path(stem + ".json");
        const std::string mask = box.path(stem + "_host.png"), exr = box.path(stem + ".exr");
        if (test::runCli("import " + shellQuoted(frag) + " -o " + shellQuoted(json) + " -q").exitCode != 0)
            continue;  // refused: frag_import_test checks the reasons
        const test::CliRun host = runHost(frag, mask);
        ASSERT_EQ(host.exitCode, 0) << "the host cannot run a frag fraktal imports: " << host.output;
        ASSERT_EQ(host.output.rfind("de ok ", 0), 0u) << host.output;
        // At the bench's size with FragM's hit cone, as bench/frag/run.sh renders it.
        const test::CliRun sized =
            test::runShell("python3 " + shellQuoted(test::sourceDir() / "bench/frag/at_size.py") + " " +
                           shellQuoted(json) + " " + kSize + " 2>&1");
        ASSERT_EQ(sized.exitCode, 0) << sized.output;
        const test::CliRun render =
            test::runCli("render " + shellQuoted(json) + " --spp 1 -o " + shellQuoted(exr) + " -q");
        ASSERT_EQ(render.exitCode, 0) << render.output;
        const silhouette::Agreement a =
            silhouette::compare(silhouette::readExrMask(exr), silhouette::readPngMask(mask));
        EXPECT_GE(a.iou, 0.9) << "fraktal " << a.aPixels << " px, the frag's own raytracer " << a.bPixels << " px";
        // A mask that is all or nothing agrees by accident (math_utils.frag's DE is a constant that
        // probes the includes, not a shape): only the others count as proof.
        compared += a.bPixels > 0 && a.bPixels < 160 * 120;
    }
    EXPECT_GE(compared, 3) << "too few of the tests' frags import and show a shape to prove anything";
}

// A raytracer whose trace() gives no verdict the host can read is named, not guessed at.
TEST(FragHost, NamesARaytracerItCannotObserve) {
    const test::Sandbox box("fraktal_frag_host_slicer_");
    const test::CliRun host = runHost(test::sourceDir() / "tests/data/frag/slicer_style.frag", box.path("m.png"));
    EXPECT_NE(host.exitCode, 0);
    EXPECT_NE(host.output.find("fail"), std::string::npos) << host.output;
    EXPECT_NE(host.output.find("trace()"), std::string::npos) << host.output;
}
