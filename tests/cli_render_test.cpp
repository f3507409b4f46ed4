// `fraktal render` and `fraktal info` from the outside: bad input is a clear error with a
// non-zero exit that leaves existing files alone; Ctrl-C leaves nothing; memory stays bounded.
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <thread>

#include "test_support.hpp"

namespace fraktal {
namespace {

namespace fs = std::filesystem;
using test::runCli;

// A sandbox named for this file's tests.
struct Sandbox : test::Sandbox {
    Sandbox() : test::Sandbox("fraktal_cli_") {}
};

std::string preset(const std::string& name) { return test::shippedPresetFile(name + ".json"); }

std::string readFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(CliRender, RendersExrAndPngAndInfoPrintsThePreset) {
    Sandbox box;
    const auto r = runCli("render " + preset("menger") + " -o " + box.path("a.exr") + " --png " + box.path("a.png") +
                          " --size 64x48 --spp 2");
    ASSERT_EQ(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("progress:"), std::string::npos) << "plain progress lines when not a TTY";
    EXPECT_EQ(box.fileCount(), 2);
    const auto info = runCli("info " + box.path("a.exr"));
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("\"Menger sponge\""), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("64 x 48"), std::string::npos) << info.output;
    // Re-render from the EXR's embedded preset: same size and samples, same pixels.
    const auto again = runCli("render " + box.path("a.exr") + " -o " + box.path("b.exr") + " -q");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    EXPECT_NE(runCli("info " + box.path("b.exr")).output.find("64 x 48"), std::string::npos);
}

// One float channel of an EXR, rows from the top.
std::vector<float> readChannel(const std::string& path, const char* name, int& width, int& height) {
    Imf::InputFile in(path.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    width = dw.max.x - dw.min.x + 1;
    height = dw.max.y - dw.min.y + 1;
    std::vector<float> data(size_t(width) * size_t(height));
    Imf::FrameBuffer fb;
    fb.insert(name, Imf::Slice(Imf::FLOAT, (char*)data.data(), sizeof(float), sizeof(float) * size_t(width)));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    return data;
}

// A 2D still keeps its preset under its own attribute: `fraktal info` prints it and `fraktal
// render STILL.exr` renders the same image again (its size, samples and view, not the file's).
TEST(CliRender, A2dStillReRendersFromItsExrToTheSameImage) {
    Sandbox box;
    const std::string julia = test::shippedPresetFile("2d/julia.json");
    const auto first = runCli("render " + julia + " -o " + box.path("a.exr") + " --size 24x16 --spp 2 --float -q");
    ASSERT_EQ(first.exitCode, 0) << first.output;
    const auto info = runCli("info " + box.path("a.exr"));
    ASSERT_EQ(info.exitCode, 0) << info.output;
    EXPECT_NE(info.output.find("2D preset (fraktal.planePreset)"), std::string::npos) << info.output;
    EXPECT_NE(info.output.find("\"Julia set"), std::string::npos) << info.output;
    EXPECT_EQ(info.output.find("no embedded"), std::string::npos) << info.output;

    const auto again = runCli("render " + box.path("a.exr") + " -o " + box.path("b.exr") + " --float -q");
    ASSERT_EQ(again.exitCode, 0) << again.output;
    for (const char* channel : {"R", "G", "B", "inside", "iterations"}) {
        int w1 = 0, h1 = 0, w2 = 0, h2 = 0;
        const std::vector<float> a = readChannel(box.path("a.exr"), channel, w1, h1);
        const std::vector<float> b = readChannel(box.path("b.exr"), channel, w2, h2);
        EXPECT_EQ(w2, 24) << "the EXR's size, not the preset file's";
        EXPECT_EQ(h2, 16);
        EXPECT_EQ(a, b) << "channel " << channel;
    }
    // The image is not trivially constant (the comparison above could fail).
    int w = 0, h = 0;
    const std::vector<float> inside = readChannel(box.path("a.exr"), "inside", w, h);
    EXPECT_NE(*std::min_element(inside.begin(), inside.end()), *std::max_element(inside.begin(), inside.end()));
}

// Each bad invocation: non-zero exit, a message with `expect`, and the existing file untouched.
TEST(CliRender, BadInputIsAClearErrorAndOverwritesNothing) {
    Sandbox box;
    const std::string existing = box.path("keep.exr");
    std::ofstream(existing) << "precious";
    const std::string ok = preset("sierpinski_tetrahedron");
    struct Case {
        std::string args, env, expect;
    };
    const Case cases[] = {
        {"render " + ok + " -o /nonexistent_dir/x.exr --size 32x32", "", "does not exist"},
        {"render " + ok + " -o " + box.path("x.tiff") + " --size 32x32", "", "unknown output extension"},
        {"render " + ok + " -o " + existing + " --png " + box.path("x.jpg") + " --size 32x32", "",
         "unknown preview extension"},
        {"render " + ok + " -o " + existing + " --size 0x10", "", "--size"},
        {"render " + ok + " -o " + existing + " --size -5x10", "", "--size"},
        {"render " + ok + " -o " + existing + " --size 1000000x1000000", "", "--size"},
        {"render " + ok + " -o " + existing + " --size banana", "", "WIDTHxHEIGHT"},
        {"render " + ok + " -o " + existing + " --spp 0", "", "spp"},
        {"render " + ok + " -o " + existing + " --spp -3", "", "spp"},
        {"render " + ok + " -o " + existing + " --spp many", "", "spp"},
        {"render " + box.path("missing.json") + " -o " + existing, "", "no such file"},
        {"render " + box.path("missing.exr") + " -o " + existing, "", "no such file"},
        {"render " + ok + " -o " + existing + " --size 32x32", "OCIO=" + box.path("broken.ocio"), "OCIO config"},
        {"render " + ok + " -o " + existing + " --size 32x32 --view Nope", "", "no view 'Nope'"},
        {"render " + ok + " -o " + existing + " --size 32x32 --working-space Nope", "", "no colour space"},
        {"info " + box.path("missing.exr"), "", "no such file"},
    };
    std::ofstream(box.path("broken.ocio"))
        << "ocio_profile_version: 2.1\nroles: {scene_linear: nowhere}\ndisplays: [\n";
    for (const Case& c : cases) {
        const auto r = runCli(c.args, c.env);
        EXPECT_GT(r.exitCode, 0) << c.args << "\n" << r.output;
        EXPECT_NE(r.output.find(c.expect), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_EQ(readFile(existing), "precious") << c.args;
    }
    EXPECT_EQ(box.fileCount(), 2) << "no temporary or partial files";  // keep.exr, broken.ocio
}

TEST(CliRender, UnwritableFolderIsRefused) {
    if (::geteuid() == 0) {
        // root writes anywhere: check a path whose parent is a file instead.
        Sandbox box;
        std::ofstream(box.path("file")) << "x";
        const auto r = runCli("render " + preset("menger") + " -o " + box.path("file") + "/x.exr --size 16x16");
        EXPECT_GT(r.exitCode, 0) << r.output;
        EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
        return;
    }
    Sandbox box;
    fs::create_directories(box.dir / "ro");
    fs::permissions(box.dir / "ro", fs::perms::owner_read | fs::perms::owner_exec);
    const auto r = runCli("render " + preset("menger") + " -o " + box.path("ro/x.exr") + " --size 16x16");
    EXPECT_GT(r.exitCode, 0) << r.output;
    EXPECT_NE(r.output.find("cannot write"), std::string::npos) << r.output;
    fs::permissions(box.dir / "ro", fs::perms::owner_all);
}

// Runs the CLI as a child; returns its exit status and peak RSS (KiB) from getrusage.
std::pair<int, long> runChild(const std::vector<std::string>& args, int interruptAfterMs = -1) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::vector<char*> argv{const_cast<char*>(FRAKTAL_CLI)};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::freopen("/dev/null", "w", stderr);
        ::execv(FRAKTAL_CLI, argv.data());
        ::_exit(127);
    }
    if (interruptAfterMs >= 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(interruptAfterMs));
        ::kill(pid, SIGINT);
    }
    int status = 0;
    struct rusage usage {};
    ::wait4(pid, &status, 0, &usage);
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, usage.ru_maxrss};
}

// A cheap scene: few iterations, no shadows or AO, few march steps.
std::string writeCheapPreset(const Sandbox& box) {
    const std::string path = box.path("cheap.json");
    std::ofstream(path) << R"({"format":"fraktal-preset","version":1,
      "formula":{"iterations":4,"bailout":1000,"boundRadius":1.8,"nodes":[{"block":"sierpinski_fold"},
        {"block":"scale","params":{"scale":2.0,"center":[1.0,1.0,1.0]}},{"block":"tetrahedron","params":{"size":1.0}}]},
      "camera":{"position":[2.2,1.4,3.1],"target":[0,-0.1,0]},
      "render":{"spp":1,"maxSteps":8},"shading":{"shadowSteps":0,"aoSteps":0}})";
    return path;
}

TEST(CliRender, LargeImagePeakMemoryIsBounded) {
    Sandbox box;
    const std::string cheap = writeCheapPreset(box);
    // 8192x8192 at 1 spp, as the issue suggests: the full-image float buffers alone would take
    // 67 Mpixel * 64 B = 4.3 GB. It takes 40-60 s on 2 shared cores (bench/README.md, Stills), most
    // of it llvmpipe running the shader; the 16384x16384 bound itself is measured there, not here.
    const auto [code, peakKiB] = runChild({"render", cheap, "-o", box.path("big.exr"), "--size", "8192x8192", "-q"});
    ASSERT_EQ(code, 0);
    std::printf("peak RSS %.0f MiB\n", peakKiB / 1024.0);
    EXPECT_LT(peakKiB, 400L * 1024) << "strips must stream to the EXR";
    EXPECT_TRUE(fs::exists(box.path("big.exr")));
}

TEST(CliRender, InterruptLeavesNoFile) {
    Sandbox box;
    const std::string existing = box.path("out.exr");
    std::ofstream(existing) << "precious";
    const auto [code, peak] = runChild({"render", preset("mandelbulb"), "-o", existing, "--png", box.path("out.png"),
                                        "--size", "1024x1024", "--spp", "16", "--tile", "64"},
                                       1500);
    EXPECT_EQ(code, 130);
    EXPECT_EQ(readFile(existing), "precious");
    EXPECT_FALSE(fs::exists(box.path("out.png")));
    EXPECT_EQ(box.fileCount(), 1) << "temporary files left behind";
}

}  // namespace
}  // namespace fraktal
