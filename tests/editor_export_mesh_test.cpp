// The mesh export dialog's job runs the real `fraktal mesh` with the flags its options map to:
// the file appears and reads back as a mesh, Done only for a mesher that exited 0 having written
// it, the mesher's error shown when it fails, and a cancel stops it without leaving a file (nor
// the temporary preset, nor the mesher's temporary output) while the caller never blocks.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "app/editor/document/mesh_export_job.hpp"
#include "core/mesh/mesh_file.hpp"
#include "editor_test_support.hpp"

namespace fraktal::editor {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> folderNames(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir)) names.push_back(e.path().filename().string());
    return names;
}

struct EditorMeshExportJob : ::testing::Test {
    fs::path dir = fs::temp_directory_path() / ("fraktal_mesh_export_" + std::to_string(::getpid()));
    MeshExportJob job;
    void SetUp() override {
        fs::remove_all(dir);
        fs::create_directories(dir);
        job.executable = FRAKTAL_CLI;
    }
    void TearDown() override {
        finishExport(job);
        fs::remove_all(dir);
    }
    std::string presetText(const char* name) { return documentFileText(test::documentFrom(name)); }
};

TEST(EditorMeshExport, EachOptionMapsToItsFlag) {
    MeshExportOptions o;
    o.output = "out/sponge.ply";
    o.resolution = 96;
    const std::vector<std::string> plain{"fraktal", "mesh", "p.json", "-o", "out/sponge.ply", "--resolution", "96"};
    EXPECT_EQ(meshExportCommand("fraktal", "p.json", o), plain) << "simplify 0 and no print size add no flags";
    o.simplify = 0.25;
    o.printSizeMm = " 120 ";
    const std::vector<std::string> full{"fraktal",        "mesh",         "p.json", "-o",
                                        "out/sponge.ply", "--resolution", "96",     "--simplify",
                                        "0.25",           "--print-size", "120mm"};
    EXPECT_EQ(meshExportCommand("fraktal", "p.json", o), full);
    o.output = "out/sponge.vdb";
    const std::vector<std::string> vdb{"fraktal",      "mesh", "p.json",     "-o",  "out/sponge.vdb",
                                       "--resolution", "96",   "--simplify", "0.25"};
    EXPECT_EQ(meshExportCommand("fraktal", "p.json", o), vdb) << "a level set never gets --print-size";
    EXPECT_EQ(meshOptionsError(o), "") << "the print size is left out for a .vdb, not refused";

    o.output = "out/sponge.glb";
    o.simplify = 0.0;
    o.printSizeMm = "";
    o.removeCavities = true;
    o.minThickness = 0.02;
    o.vertexColours = false;
    const std::vector<std::string> printing{"fraktal",         "mesh",         "p.json",    "-o",
                                            "out/sponge.glb",  "--resolution", "96",        "--remove-cavities",
                                            "--min-thickness", "0.02",         "--no-color"};
    EXPECT_EQ(meshExportCommand("fraktal", "p.json", o), printing);
    o.output = "out/sponge.stl";
    EXPECT_EQ(meshExportCommand("fraktal", "p.json", o).back(), "0.02") << "STL carries no colours: no --no-color";
    EXPECT_FALSE(meshFormatCarriesColours(o.output));
    EXPECT_TRUE(meshFormatCarriesColours("a.ply"));
}

TEST(EditorMeshExport, TheExtensionIsTheFormat) {
    EXPECT_EQ(meshFormat("a/b.PLY"), ".ply");
    EXPECT_EQ(meshFormat("a/b.glb"), ".glb");
    EXPECT_EQ(meshFormat("a/b.fbx"), "");
    EXPECT_EQ(meshFormat("a/b"), "");
    EXPECT_EQ(withMeshFormat("a/b.ply", ".stl"), "a/b.stl");
    EXPECT_EQ(withMeshFormat("a/b", ".glb"), "a/b.glb");
    EXPECT_EQ(withMeshFormat("a/b.c.ply", ".vdb"), "a/b.c.vdb");
    MeshExportOptions o;
    o.output = "a/b.fbx";
    EXPECT_NE(meshOptionsError(o).find(".ply, .glb, .obj, .stl, .vdb"), std::string::npos) << meshOptionsError(o);
    o.output = "a/b.stl";
    o.printSizeMm = "ten";
    EXPECT_NE(meshOptionsError(o).find("millimetres"), std::string::npos) << meshOptionsError(o);
    o.printSizeMm = "-5";
    EXPECT_NE(meshOptionsError(o), "");
    o.printSizeMm = "";
    EXPECT_EQ(meshOptionsError(o), "");
}

TEST(EditorMeshExport, VoxelSizeAndProgressStage) {
    const Formula f = test::shippedPreset("menger.json").formula;
    EXPECT_NEAR(meshVoxelSize(f, 100), 2.0 * f.boundRadius / 100.0, 1e-12);
    const std::string log = "p.json: 32^3 voxels\nprogress: planning bricks (10%)\nprogress: sampling bricks (40%)\n";
    EXPECT_EQ(meshProgressStage(log), "sampling bricks");
    EXPECT_NEAR(parseProgress(log), 0.4, 1e-12);
    EXPECT_EQ(meshProgressStage("p.json: 32^3 voxels\n"), "");
}

TEST_F(EditorMeshExportJob, MeshesTheDocumentIntoAFileThatReadsBack) {
    job.options.output = (dir / "sponge.ply").string();
    job.options.resolution = 32;
    const auto start = std::chrono::steady_clock::now();
    ASSERT_TRUE(startMeshExport(job, presetText("menger.json"), 0.0)) << job.log;
    ASSERT_TRUE(test::pollUntilEnded(job, 120.0)) << job.log;
    std::printf("meshed in %.1f s: %s\n",
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                meshExportStatusText(job).c_str());
    ASSERT_EQ(job.status, ExportStatus::Done) << job.log;
    // The mesher's progress lines ("progress: meshing (95%)", over the whole job) reach the dialog.
    EXPECT_GE(job.progress, 0.9) << job.log;
    EXPECT_EQ(meshProgressStage(job.log), "meshing") << job.log;
    const mesh::TriangleMesh m = mesh::readMesh(dir / "sponge.ply");
    EXPECT_GT(m.triangles.size(), 100u);
    EXPECT_EQ(meshExportStatusText(job).rfind("Done: " + (dir / "sponge.ply").string(), 0), 0u)
        << meshExportStatusText(job);
    EXPECT_EQ(folderNames(dir), std::vector<std::string>{"sponge.ply"}) << "the temporary preset is removed";

    // Done only while the file it wrote is there.
    fs::remove(dir / "sponge.ply");
    EXPECT_EQ(meshExportStatusText(job).find("Done"), std::string::npos) << meshExportStatusText(job);
}

TEST_F(EditorMeshExportJob, AFailureShowsTheMeshersError) {
    Document d;
    d.plane = loadPlanePreset(fs::path(FRAKTAL_SOURCE_DIR) / "presets" / "2d" / "sierpinski_triangle.json");
    job.options.output = (dir / "plane.stl").string();
    job.options.resolution = 32;
    ASSERT_TRUE(startMeshExport(job, documentFileText(d), 0.0)) << job.log;
    ASSERT_TRUE(test::pollUntilEnded(job, 60.0)) << job.log;
    EXPECT_EQ(job.status, ExportStatus::Failed);
    EXPECT_NE(meshExportStatusText(job).find("2D preset has no surface to mesh"), std::string::npos)
        << meshExportStatusText(job);
    EXPECT_TRUE(folderNames(dir).empty());

    // A mesher that exits 0 without writing the file: Failed, naming the file.
    const fs::path fake = dir / "fake_mesher.sh";
    std::ofstream(fake) << "#!/bin/sh\necho progress: meshing '(100%)'\nexit 0\n";
    fs::permissions(fake, fs::perms::owner_all);
    job.executable = fake;
    job.options.output = (dir / "never.glb").string();
    ASSERT_TRUE(startMeshExport(job, presetText("menger.json"), 0.0)) << job.log;
    ASSERT_TRUE(test::pollUntilEnded(job, 30.0)) << job.log;
    EXPECT_EQ(job.status, ExportStatus::Failed);
    EXPECT_EQ(meshExportStatusText(job), "Failed: the mesher exited without writing " + (dir / "never.glb").string());

    // Options that cannot be meshed start nothing.
    job.options.output = (dir / "sponge.fbx").string();
    EXPECT_FALSE(startMeshExport(job, presetText("menger.json"), 0.0));
    EXPECT_EQ(job.status, ExportStatus::Failed);
    EXPECT_EQ(job.pid, -1);
}

TEST_F(EditorMeshExportJob, CancelReturnsAtOnceAndLeavesNoFile) {
    job.options.output = (dir / "bulb.ply").string();
    job.options.resolution = 1024;
    ASSERT_TRUE(startMeshExport(job, presetText("mandelbulb.json"), 0.0)) << job.log;
    // Until the mesher reports progress, or 1.5 s: past its start, within its sampling.
    const auto end = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
    while (job.progress <= 0.0 && std::chrono::steady_clock::now() < end) {
        pollExport(job);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    ASSERT_EQ(job.status, ExportStatus::Running) << "the mesher ended before the cancel: " << job.log;
    test::expectCancelReturnsAtOnce(job, 60.0);
    if (HasFatalFailure()) return;
    EXPECT_EQ(meshExportStatusText(job), "Cancelled: no file written.");
    EXPECT_TRUE(folderNames(dir).empty()) << "no mesh, no temporary preset, no temporary output";
}

}  // namespace
}  // namespace fraktal::editor
