// `fraktal encode`: a frame sequence into H.264, ProRes and FFV1 video through ffmpeg; what ffprobe
// reads back (frames, size, codec, rate) and frame 0 decoded again, against the OCIO display
// transform of the EXR; gaps, bad frames and a missing or failing ffmpeg are clear errors with no
// video (and no temporary file) left behind.
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfRgbaFile.h>
#include <ImfStringAttribute.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "core/color/color_pipeline.hpp"
#include "core/image/exr_writer.hpp"
#include "test_support.hpp"

using namespace fraktal;

namespace {

std::filesystem::path freshFolder(const std::string& name) {
    const auto dir = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

std::string run(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    std::string out;
    char buf[65536];
    for (size_t n; (n = fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    pclose(pipe);
    return out;
}

nlohmann::json probe(const std::filesystem::path& video) {
    return nlohmann::json::parse(
        run("ffprobe -v error -count_frames -select_streams v:0 -show_entries "
            "stream=codec_name,width,height,nb_read_frames,pix_fmt,r_frame_rate -of json " +
            video.string()))["streams"][0];
}

// Frame 0 of `video` decoded to 8-bit RGB by ffmpeg (BT.709 Y'CbCr to RGB, as tagged).
std::vector<uint8_t> decodeFrame0(const std::filesystem::path& video) {
    const std::string raw =
        run("ffmpeg -v error -i " + video.string() +
            " -frames:v 1 -vf scale=in_color_matrix=bt709:in_range=tv -f rawvideo -pix_fmt rgb24 -");
    return std::vector<uint8_t>(raw.begin(), raw.end());
}

// The EXR's colour through the display transform the still exporter's PNG uses (sRGB, Standard).
std::vector<uint8_t> displayed(const std::filesystem::path& exr) {
    Imf::InputFile in(exr.c_str());
    const Imath::Box2i dw = in.header().dataWindow();
    const int w = dw.max.x - dw.min.x + 1, h = dw.max.y - dw.min.y + 1;
    std::vector<float> rgba(size_t(w) * size_t(h) * 4, 1.0f);
    Imf::FrameBuffer fb;
    const char* names[] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c)
        fb.insert(names[c], Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(rgba.data() + c), 4 * sizeof(float),
                                       4 * sizeof(float) * size_t(w)));
    in.setFrameBuffer(fb);
    in.readPixels(dw.min.y, dw.max.y);
    const auto* declared = in.header().findTypedAttribute<Imf::StringAttribute>(kExrWorkingSpaceAttribute);
    const std::string space = declared ? declared->value() : "scene_linear";
    const ColorPipeline color = ColorPipeline::fromEnvironment();
    std::vector<uint8_t> rgb(size_t(w) * size_t(h) * 3);
    DisplayTransform(color, color.resolveSpace(space), "sRGB", "Standard", 0.0).toDisplay8(rgba, rgb);
    return rgb;
}

struct Difference {
    double mean = 0;
    int max = 0;
};
Difference compare(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    Difference d;
    for (size_t i = 0; i < a.size(); ++i) {
        const int e = std::abs(int(a[i]) - int(b[i]));
        d.mean += e;
        d.max = std::max(d.max, e);
    }
    d.mean /= double(a.size());
    return d;
}

// Mean |difference| of BT.709 luma (Y' from R'G'B'), which 4:2:0 and 4:2:2 keep at full resolution.
double meanLumaError(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    double sum = 0;
    for (size_t i = 0; i + 2 < a.size(); i += 3)
        sum += std::abs(0.2126 * (a[i] - b[i]) + 0.7152 * (a[i + 1] - b[i + 1]) + 0.0722 * (a[i + 2] - b[i + 2]));
    return sum / double(a.size() / 3);
}

// Frames of four flat quadrants of saturated colour (a plain EXR: no fraktal attributes), where
// chroma subsampling costs nothing away from the edges and a wrong Y'CbCr matrix or range shows.
constexpr int kPatchW = 64, kPatchH = 32;
void writePatchFrames(const std::filesystem::path& dir, int count, int width = kPatchW, int height = kPatchH) {
    const float colours[4][3] = {{0.8f, 0.05f, 0.05f}, {0.05f, 0.6f, 0.05f}, {0.05f, 0.05f, 0.8f}, {0.9f, 0.7f, 0.1f}};
    std::vector<Imf::Rgba> pixels(size_t(width) * height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float* c = colours[(y >= height / 2) * 2 + (x >= width / 2)];
            pixels[size_t(y) * width + x] = Imf::Rgba(c[0], c[1], c[2], 1.0f);
        }
    for (int i = 0; i < count; ++i) {
        char name[32];
        std::snprintf(name, sizeof name, "p_%03d.exr", i);
        Imf::RgbaOutputFile out((dir / name).c_str(), width, height, Imf::WRITE_RGBA);
        out.setFrameBuffer(pixels.data(), 1, width);
        out.writePixels(height);
    }
}

// The largest error over the quadrants' inner pixels (4 pixels away from every colour edge).
int maxInnerError(const std::vector<uint8_t>& a, const std::vector<uint8_t>& b) {
    int worst = 0;
    for (int y = 0; y < kPatchH; ++y)
        for (int x = 0; x < kPatchW; ++x) {
            if (std::abs(x - kPatchW / 2) < 4 || std::abs(y - kPatchH / 2) < 4) continue;
            for (int c = 0; c < 3; ++c) {
                const size_t i = (size_t(y) * kPatchW + x) * 3 + c;
                worst = std::max(worst, std::abs(int(a[i]) - int(b[i])));
            }
        }
    return worst;
}

std::vector<std::string> leftovers(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().extension() != ".exr") names.push_back(e.path().filename().string());
    return names;
}

}  // namespace

TEST(Encode, FramesIntoVideoThroughTheDisplayTransform) {
    const auto dir = freshFolder("fraktal_encode_test");
    // The power morph at 30 fps: the frame rate travels in the frames' embedded preset.
    nlohmann::json preset =
        nlohmann::json::parse(std::ifstream(test::sourceDir() / "presets/mandelbulb_power_morph.json"));
    preset["animation"]["fps"] = 30;
    std::ofstream(dir / "anim.json") << preset.dump(2);
    std::filesystem::create_directories(dir / "frames");
    const std::string pattern = (dir / "frames/f_####.exr").string();
    const test::CliRun render =
        test::runCli("render " + (dir / "anim.json").string() + " -q --frames 0-5 --size 64x36 --spp 1 -o " + pattern);
    ASSERT_EQ(render.exitCode, 0) << render.output;
    const std::vector<uint8_t> reference = displayed(dir / "frames/f_0000.exr");
    ASSERT_EQ(reference.size(), 64u * 36u * 3u);
    int lit = 0;
    for (uint8_t v : reference) lit += v > 20;
    ASSERT_GT(lit, 500) << "frame 0 is nearly black: nothing to compare";

    struct Case {
        const char *codec, *file;
        double maxMeanLumaError;
    };
    // FFV1 is lossless RGB. H.264 (4:2:0, CRF 18) and ProRes 422 HQ keep luma at full resolution;
    // on this small, detailed frame their luma differs by 2.5 and 3.2 levels on average (measured).
    for (const Case& c : {Case{"ffv1", "a.mkv", 0.5}, Case{"h264", "a.mp4", 4.0}, Case{"prores", "a.mov", 4.5}}) {
        const auto video = dir / c.file;
        const test::CliRun encode =
            test::runCli("encode -q " + pattern + " -o " + video.string() + " --codec " + c.codec);
        ASSERT_EQ(encode.exitCode, 0) << encode.output;
        const nlohmann::json s = probe(video);
        EXPECT_EQ(s.value("codec_name", ""), c.codec) << s;
        EXPECT_EQ(s.value("nb_read_frames", ""), "6") << s;
        EXPECT_EQ(s.value("width", 0), 64) << s;
        EXPECT_EQ(s.value("height", 0), 36) << s;
        EXPECT_EQ(s.value("r_frame_rate", ""), "30/1") << s;
        const std::vector<uint8_t> decoded = decodeFrame0(video);
        ASSERT_EQ(decoded.size(), reference.size()) << c.codec;
        const Difference d = compare(decoded, reference);
        const double luma = meanLumaError(decoded, reference);
        std::printf("%s: frame 0 against the display transform: mean |error| %.3f, max %d, luma %.3f (of 255)\n",
                    c.codec, d.mean, d.max, luma);
        EXPECT_LE(luma, c.maxMeanLumaError) << c.codec;
        if (std::string(c.codec) == "ffv1") {
            EXPECT_LE(d.max, 1) << "FFV1 must be exact (rgb24 path)";
        }
    }
    // Flat colours: away from the edges every codec gives the display-transformed colour back
    // (measured: H.264 within 6 levels, ProRes 3, FFV1 0; decoding with the BT.601 matrix
    // instead is off by 11 to 24 levels on these colours).
    std::filesystem::create_directories(dir / "patches");
    writePatchFrames(dir / "patches", 3);
    const std::vector<uint8_t> patchReference = displayed(dir / "patches/p_000.exr");
    for (const char* codec : {"h264", "prores", "ffv1"}) {
        const auto video = dir / (std::string("patches.") + codec + ".mkv");
        const test::CliRun encode = test::runCli("encode -q " + (dir / "patches/p_###.exr").string() + " -o " +
                                                 video.string() + " --codec " + codec);
        ASSERT_EQ(encode.exitCode, 0) << encode.output;
        EXPECT_EQ(probe(video).value("r_frame_rate", ""), "24/1") << "no embedded rate: 24 fps";
        const std::vector<uint8_t> decoded = decodeFrame0(video);
        ASSERT_EQ(decoded.size(), patchReference.size()) << codec;
        const int worst = maxInnerError(decoded, patchReference);
        std::printf("%s: flat colours, largest inner error %d (of 255)\n", codec, worst);
        EXPECT_LE(worst, std::string(codec) == "ffv1" ? 1 : std::string(codec) == "h264" ? 8 : 5) << codec;
    }
    EXPECT_EQ(probe(dir / "a.mp4").value("pix_fmt", ""), "yuv420p");
    // --fps overrides the embedded rate.
    ASSERT_EQ(test::runCli("encode -q " + pattern + " --fps 12 -o " + (dir / "b.mp4").string()).exitCode, 0);
    EXPECT_EQ(probe(dir / "b.mp4").value("r_frame_rate", ""), "12/1");
    std::filesystem::remove(dir / "b.mp4");

    // A gap: named, no video; --allow-gaps encodes the frames there are.
    std::filesystem::rename(dir / "frames/f_0003.exr", dir / "f_0003.exr");
    const auto gapVideo = (dir / "gap.mp4").string();
    const test::CliRun gap = test::runCli("encode -q " + pattern + " -o " + gapVideo);
    EXPECT_EQ(gap.exitCode, 2);
    EXPECT_NE(gap.output.find("1 frame(s) missing between 0 and 5 (3)"), std::string::npos) << gap.output;
    EXPECT_NE(gap.output.find("f_0003.exr"), std::string::npos) << gap.output;
    EXPECT_FALSE(std::filesystem::exists(gapVideo));
    ASSERT_EQ(test::runCli("encode -q --allow-gaps " + pattern + " -o " + gapVideo).exitCode, 0);
    EXPECT_EQ(probe(gapVideo).value("nb_read_frames", ""), "5");
    std::filesystem::rename(dir / "f_0003.exr", dir / "frames/f_0003.exr");

    // ffmpeg missing, ffmpeg failing, an output ffmpeg cannot write: named, exit 2, nothing left.
    const auto out = dir / "out/x.mp4";
    std::filesystem::create_directories(out.parent_path());
    const test::CliRun missing =
        test::runCli("encode -q " + pattern + " --ffmpeg /nonexistent/ffmpeg -o " + out.string());
    EXPECT_EQ(missing.exitCode, 2);
    EXPECT_NE(missing.output.find("cannot run /nonexistent/ffmpeg"), std::string::npos) << missing.output;
    const test::CliRun failing = test::runCli("encode -q " + pattern + " --ffmpeg false -o " + out.string());
    EXPECT_EQ(failing.exitCode, 2);
    EXPECT_NE(failing.output.find("false failed (exit status 1)"), std::string::npos) << failing.output;
    const test::CliRun unknownFormat =
        test::runCli("encode -q " + pattern + " -o " + (dir / "out/x.nosuchformat").string());
    EXPECT_EQ(unknownFormat.exitCode, 2);
    EXPECT_NE(unknownFormat.output.find("ffmpeg failed"), std::string::npos) << unknownFormat.output;
    EXPECT_NE(unknownFormat.output.find("x.nosuchformat"), std::string::npos) << unknownFormat.output;
    EXPECT_TRUE(std::filesystem::is_empty(out.parent_path())) << leftovers(out.parent_path()).front();

    // A frame that is not an EXR: named before ffmpeg starts.
    std::ofstream(dir / "frames/f_0006.exr") << "not an image";
    const test::CliRun notExr = test::runCli("encode -q " + pattern + " -o " + out.string());
    EXPECT_EQ(notExr.exitCode, 2);
    EXPECT_NE(notExr.output.find("f_0006.exr: not a readable EXR frame"), std::string::npos) << notExr.output;
    EXPECT_TRUE(std::filesystem::is_empty(out.parent_path()));
    const test::CliRun noFrames =
        test::runCli("encode -q " + (dir / "out/g_####.exr").string() + " -o " + out.string());
    EXPECT_EQ(noFrames.exitCode, 2);
    EXPECT_NE(noFrames.output.find("no frames found"), std::string::npos) << noFrames.output;
    const test::CliRun noFolder =
        test::runCli("encode -q " + (dir / "nowhere/f_####.exr").string() + " -o " + out.string());
    EXPECT_EQ(noFolder.exitCode, 2);
    EXPECT_NE(noFolder.output.find("no frame folder " + (dir / "nowhere").string()), std::string::npos)
        << noFolder.output;
    std::filesystem::remove_all(dir);
}

// Ctrl+C while encoding: ffmpeg is stopped, its temporary video removed, and the video that was at
// the destination before stays as it was.
TEST(Encode, InterruptKeepsTheOldVideoAndLeavesNoTemporaryFile) {
    const auto dir = freshFolder("fraktal_encode_interrupt");
    std::filesystem::create_directories(dir / "frames");
    writePatchFrames(dir / "frames", 200, 640, 360);
    const std::string pattern = (dir / "frames/p_###.exr").string(), video = (dir / "v.mp4").string();
    std::ofstream(video) << "precious";
    auto temporaries = [&dir] {
        int n = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir))
            n += e.path().filename().string().starts_with(".v.tmp-");
        return n;
    };
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::freopen("/dev/null", "w", stderr);
        ::execl(FRAKTAL_CLI, FRAKTAL_CLI, "encode", "-q", pattern.c_str(), "-o", video.c_str(), nullptr);
        ::_exit(127);
    }
    ASSERT_GT(pid, 0);
    // Interrupt once ffmpeg has begun writing the temporary video (it makes it with its header).
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (temporaries() == 0 && std::chrono::steady_clock::now() < deadline)
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    const bool started = temporaries() > 0;
    ::kill(pid, SIGINT);
    int status = 0;
    ::waitpid(pid, &status, 0);
    ASSERT_TRUE(started) << "no temporary video appeared within 30 s";
    ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status) << ": Ctrl+C was not handled";
    EXPECT_EQ(WEXITSTATUS(status), 130) << "cancelled is exit status 130";
    std::ifstream in(video);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "precious");
    EXPECT_EQ(temporaries(), 0) << "a temporary video was left behind";
}
