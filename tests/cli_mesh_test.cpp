// `fraktal mesh`: files that reopen and print, animation frames, and bad input refused with a
// clear error and nothing written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/animation.hpp"
#include "core/mesh/mesh_file.hpp"
#include "core/mesh/sdf_volume.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

std::string bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(CliMesh, StlReopensClosedAndScaledToThePrintSize) {
    test::Sandbox box("fraktal_cli_mesh_stl_");
    const test::CliRun run = test::runCli("mesh " + test::shippedPresetFile("mandelbulb.json") +
                                          " --resolution 48 --print-size 10cm --threads 2 -o " + box.path("bulb.stl"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const mesh::TriangleMesh m = mesh::readMesh(box.path("bulb.stl"));
    const mesh::ManifoldReport r = mesh::checkManifold(m);
    EXPECT_EQ(r.boundaryEdges, 0);
    EXPECT_EQ(r.overSharedEdges, 0);
    EXPECT_EQ(r.misorientedEdges, 0);
    const auto bounds = m.bounds();
    const vec3 extent = bounds[1] - bounds[0];
    EXPECT_NEAR(std::max(extent.x, std::max(extent.y, extent.z)), 100.0, 1e-3);
    EXPECT_GT(m.enclosedVolume(), 0.0);
    EXPECT_NE(run.output.find("triangles"), std::string::npos) << run.output;
}

TEST(CliMesh, VdbReopensAsALevelSet) {
    test::Sandbox box("fraktal_cli_mesh_vdb_");
    const test::CliRun run = test::runCli("mesh " + test::shippedPresetFile("mandelbulb.json") +
                                          " --resolution 40 --threads 2 -o " + box.path("bulb.vdb"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    const mesh::VdbSummary vdb = mesh::readVdb(box.path("bulb.vdb"));
    EXPECT_EQ(vdb.grids, 1);
    EXPECT_EQ(vdb.gridClass, "level set");
    EXPECT_NEAR(vdb.voxelSize, 3.0 / 40.0, 1e-9);
    EXPECT_GT(vdb.activeVoxels, 1000);
    EXPECT_LT(vdb.sample(vec3(0.0)), 0.0) << "the bulb's centre is inside";
    EXPECT_GT(vdb.sample(vec3(1.45, 1.45, 1.45)), 0.0) << "the bound's corner is outside";
    // OpenVDB's own tool (libopenvdb-tools) reads it: one float level set named as written.
    const test::CliRun print = test::runShell("vdb_print -l " + box.path("bulb.vdb") + " 2>&1");
    ASSERT_EQ(print.exitCode, 0) << print.output;
    EXPECT_NE(print.output.find(mesh::kVdbGridName), std::string::npos) << print.output;
    EXPECT_NE(print.output.find("float"), std::string::npos) << print.output;
    EXPECT_NE(print.output.find("level set"), std::string::npos) << print.output;
}

// --frames A-B:STEP writes one file per frame, each the mesh of that frame (as --frame N).
TEST(CliMesh, FramesWriteOneMeshPerFrame) {
    test::Sandbox box("fraktal_cli_mesh_frames_");
    const std::string animated = test::shippedPresetFile("mandelbulb_power_morph.json");
    const std::string options = " --resolution 32 --threads 2";
    const test::CliRun run =
        test::runCli("mesh " + animated + " --frames 100-140:20" + options + " -o " + box.path("bulb_####.ply"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_EQ(box.fileCount(), 3);
    const test::CliRun one = test::runCli("mesh " + animated + " --frame 120" + options + " -o " + box.path("one.ply"));
    ASSERT_EQ(one.exitCode, 0) << one.output;
    EXPECT_EQ(bytes(box.path("bulb_0120.ply")), bytes(box.path("one.ply")));
    EXPECT_NE(bytes(box.path("bulb_0100.ply")), bytes(box.path("bulb_0140.ply")));
    EXPECT_NE(run.output.find("frame 3/3 (140)"), std::string::npos) << run.output;
    // A pattern without a run of # is refused before any work.
    const test::CliRun bad =
        test::runCli("mesh " + animated + " --frames 0-2" + options + " -o " + box.path("plain.ply"));
    EXPECT_NE(bad.exitCode, 0);
    EXPECT_EQ(box.fileCount(), 4) << bad.output;
}

// The printing options report what they changed, and colour goes where the format carries it.
TEST(CliMesh, PrintingOptionsReportWhatTheyChanged) {
    test::Sandbox box("fraktal_cli_mesh_print_");
    const std::string bulb = test::shippedPresetFile("mandelbulb.json");
    const test::CliRun run =
        test::runCli("mesh " + bulb + " --resolution 48 --threads 2 --remove-cavities --min-thickness 0.05 -o " +
                     box.path("bulb.glb"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("cavities: "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("voxels made solid"), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("coloured"), std::string::npos) << run.output;
    const mesh::TriangleMesh coloured = mesh::readMesh(box.path("bulb.glb"));
    EXPECT_EQ(coloured.colors.size(), coloured.points.size());
    EXPECT_TRUE(mesh::checkManifold(coloured).manifold());
    const test::CliRun plain =
        test::runCli("mesh " + bulb + " --resolution 32 --threads 2 --no-color -o " + box.path("plain.glb"));
    ASSERT_EQ(plain.exitCode, 0) << plain.output;
    EXPECT_TRUE(mesh::readMesh(box.path("plain.glb")).colors.empty());
}

// On a pipe, progress comes as "progress: STAGE (NN%)" lines (the editor's export reads them);
// SIGTERM stops the job at its next batch with 130 and leaves no file.
TEST(CliMesh, ProgressLinesAndATermLeavesNoFile) {
    test::Sandbox box("fraktal_cli_mesh_cancel_");
    const std::string bulb = test::shippedPresetFile("mandelbulb.json");
    const test::CliRun done = test::runCli("mesh " + bulb + " --resolution 48 --threads 2 -o " + box.path("small.ply"));
    ASSERT_EQ(done.exitCode, 0) << done.output;
    EXPECT_NE(done.output.find("progress: planning (0%)"), std::string::npos) << done.output;
    EXPECT_NE(done.output.find("progress: sampling ("), std::string::npos) << done.output;
    EXPECT_NE(done.output.find("progress: meshing (95%)"), std::string::npos) << done.output;
    // A mesh that takes minutes, stopped once it samples.
    const std::string big = box.path("big.ply");
    const test::CliRun stopped =
        test::runShell("(" + std::string(FRAKTAL_CLI) + " mesh " + bulb + " --resolution 1024 --threads 2 -o " + big +
                       " 2>&1 & pid=$!; for i in $(seq 600); do sleep 0.1; grep -q 'progress: sampling' " +
                       box.path("log") + " 2>/dev/null && break; done; kill -TERM $pid; wait $pid; echo exit=$?) > " +
                       box.path("log") + " 2>&1; cat " + box.path("log"));
    EXPECT_NE(stopped.output.find("exit=130"), std::string::npos) << stopped.output;
    EXPECT_NE(stopped.output.find("mesh cancelled"), std::string::npos) << stopped.output;
    EXPECT_FALSE(std::filesystem::exists(big));
    EXPECT_EQ(box.fileCount(), 2) << "small.ply and the log alone";
}

// The mesh of an animation's frame is the mesh of that frame saved as a still.
TEST(CliMesh, FrameOfAnAnimationEqualsItsStill) {
    test::Sandbox box("fraktal_cli_mesh_frame_");
    const std::string animated = test::shippedPresetFile("mandelbulb_power_morph.json");
    savePresetFile(box.path("still.json"), presetAtFrame(loadPreset(animated), 150));
    const std::string options = " --resolution 40 --threads 2 -o ";
    const test::CliRun frame = test::runCli("mesh " + animated + " --frame 150" + options + box.path("frame.ply"));
    ASSERT_EQ(frame.exitCode, 0) << frame.output;
    const test::CliRun still = test::runCli("mesh " + box.path("still.json") + options + box.path("still.ply"));
    ASSERT_EQ(still.exitCode, 0) << still.output;
    EXPECT_GT(bytes(box.path("frame.ply")).size(), 1000u);
    EXPECT_EQ(bytes(box.path("frame.ply")), bytes(box.path("still.ply")));
    // And it is not frame 0's.
    const test::CliRun first = test::runCli("mesh " + animated + " --frame 0" + options + box.path("first.ply"));
    ASSERT_EQ(first.exitCode, 0) << first.output;
    EXPECT_NE(bytes(box.path("first.ply")), bytes(box.path("still.ply")));
}

// A Fragmentarium frag's DE is GLSL alone: it is meshed on the GL probe, closed, and refused on
// the CPU by name.
TEST(CliMesh, AFragIsMeshedWithItsOwnGlsl) {
    test::Sandbox box("fraktal_cli_mesh_frag_");
    const std::string frag = std::string(FRAKTAL_TEST_DIR) + "/data/frag_import/menger.frag";
    const test::CliRun run = test::runCli("mesh " + frag + " --resolution 128 -o " + box.path("menger.ply"));
    ASSERT_EQ(run.exitCode, 0) << run.output;
    EXPECT_NE(run.output.find("on the GPU"), std::string::npos) << run.output;
    const mesh::TriangleMesh m = mesh::readMesh(box.path("menger.ply"));
    EXPECT_GT(m.triangles.size(), 1000u);
    EXPECT_TRUE(mesh::checkManifold(m).manifold());
    EXPECT_GT(m.enclosedVolume(), 0.0);
    const test::CliRun cpu = test::runCli("mesh " + frag + " --resolution 128 --device cpu -o " + box.path("cpu.ply"));
    EXPECT_NE(cpu.exitCode, 0);
    EXPECT_NE(cpu.output.find("custom GLSL blocks have no CPU version"), std::string::npos) << cpu.output;
    EXPECT_EQ(box.fileCount(), 1);
}

struct BadMesh {
    std::string args;     // after "mesh", with OUT for the sandbox's output path
    std::string message;  // a part of the error
};

TEST(CliMesh, BadInputIsRefusedAndLeavesNothing) {
    test::Sandbox box("fraktal_cli_mesh_bad_");
    const std::string blocker = box.write("file", "not a folder");
    const std::vector<BadMesh> cases = {
        {test::shippedPresetFile("menger.json") + " --resolution 1000000 -o OUT.ply", "needs about"},
        {test::shippedPresetFile("menger.json") + " -o " + blocker + "/x.ply", blocker},
        {test::shippedPresetFile("2d/mandelbrot.json") + " -o OUT.ply", "2D preset has no surface"},
        {test::shippedPresetFile("menger.json") + " -o OUT.xyz", "unknown output format \".xyz\""},
        {test::shippedPresetFile("menger.json") + " --frame 3 -o OUT.ply", "the preset has no animation"},
        {test::shippedPresetFile("mandelbulb_power_morph.json") + " --frame 999 -o OUT.ply",
         "outside the animation's frames 0-239"},
        {test::shippedPresetFile("menger.json") + " --print-size 10parsecs -o OUT.ply", "--print-size"},
        {test::shippedPresetFile("menger.json") + " --print-size 10cm -o OUT.vdb", "--print-size scales a mesh"},
        {test::shippedPresetFile("missing.json") + " -o OUT.ply", "missing.json"},
        {test::shippedPresetFile("menger.json") + " --box 0,0,0,1,-1,1 -o OUT.ply", "--box: its high corner"},
        {test::shippedPresetFile("menger.json") + " --box 0,0,0,1 -o OUT.ply", "--box"},
    };
    for (const BadMesh& c : cases) {
        std::string args = "mesh " + c.args + " --threads 2";
        const size_t out = args.find("OUT");
        if (out != std::string::npos) args.replace(out, 3, box.path("out"));
        const test::CliRun run = test::runCli(args);
        EXPECT_NE(run.exitCode, 0) << args;
        EXPECT_NE(run.exitCode, -1) << args << ": crashed";
        EXPECT_NE(run.output.find(c.message), std::string::npos) << args << "\n" << run.output;
        EXPECT_EQ(box.fileCount(), 1) << args << ": left a file";
    }
}

}  // namespace
}  // namespace fraktal
