// ExrStripWriter on its own: every channel of every pixel reads back the value the strip held
// (strided slices into the interleaved strip, half conversion, strips of any row count, several
// compression threads), and the fast float-to-half path rounds exactly like Imath.
#include "core/image/exr_writer.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>

namespace fraktal {
namespace {

namespace fs = std::filesystem;

// A distinct, exactly known value for each buffer, component and pixel.
float probe(int buffer, int component, int x, int y) {
    return float(buffer * 1000 + component * 100) + float(x) * 0.25f - float(y) * 0.5f + 0.125f;
}

struct ChannelWhere {
    const char* name;
    int buffer, component;
    bool alwaysFloat;
};
constexpr ChannelWhere kLayout[] = {{"R", 0, 0, false},        {"G", 0, 1, false},        {"B", 0, 2, false},
                                    {"A", 0, 3, false},        {"Z", 1, 3, true},         {"N.x", 1, 0, false},
                                    {"N.y", 1, 1, false},      {"N.z", 1, 2, false},      {"albedo.R", 2, 0, false},
                                    {"albedo.G", 2, 1, false}, {"albedo.B", 2, 2, false}, {"AO", 2, 3, false},
                                    {"steps", 3, 1, true}};

void writeProbeImage(const fs::path& path, int width, int height, int stripRows, bool fullFloat, int threads) {
    ExrStripWriter writer(path, width, height, fullFloat, ExrMetadata{}, threads);
    ImageStrip strip;
    for (int y0 = 0; y0 < height; y0 += stripRows) {
        strip.resize(width, y0, std::min(stripRows, height - y0));
        std::vector<float>* buffers[4] = {&strip.rgba, &strip.normalDepth, &strip.albedoAO, &strip.stats};
        for (int b = 0; b < 4; ++b)
            for (int j = 0; j < strip.rows; ++j)
                for (int x = 0; x < width; ++x)
                    for (int c = 0; c < 4; ++c) (*buffers[b])[(size_t(j) * width + x) * 4 + c] = probe(b, c, x, y0 + j);
        writer.write(strip);
    }
    writer.close();
}

void expectProbeImage(const fs::path& path, int width, int height, bool fullFloat) {
    Imf::InputFile in(path.c_str());
    for (const ChannelWhere& c : kLayout) {
        const Imf::Channel* channel = in.header().channels().findChannel(c.name);
        ASSERT_NE(channel, nullptr) << c.name;
        const bool isFloat = c.alwaysFloat || fullFloat;
        EXPECT_EQ(channel->type, isFloat ? Imf::FLOAT : Imf::HALF) << c.name;
        std::vector<float> data(size_t(width) * height);
        Imf::FrameBuffer fb;
        fb.insert(c.name, Imf::Slice(Imf::FLOAT, (char*)data.data(), sizeof(float), sizeof(float) * width));
        in.setFrameBuffer(fb);
        in.readPixels(0, height - 1);
        int wrong = 0;
        for (int y = 0; y < height; ++y)
            for (int x = 0; x < width; ++x) {
                const float v = probe(c.buffer, c.component, x, y);
                const float expected = isFloat ? v : float(half(v));
                if (data[size_t(y) * width + x] != expected && ++wrong <= 3)
                    ADD_FAILURE() << c.name << " at (" << x << ", " << y << "): " << data[size_t(y) * width + x]
                                  << " instead of " << expected;
            }
        EXPECT_EQ(wrong, 0) << c.name;
    }
}

TEST(ExrWriter, EveryChannelReadsBackWhatTheStripsHeld) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_exr_writer_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    struct Case {
        int width, height, stripRows;
        bool fullFloat;
        int threads;
    };
    // Strips of whole ZIP blocks and of odd row counts (blocks split across calls); 1 and 3 threads.
    for (const Case& k : {Case{67, 53, 16, true, 1}, Case{67, 53, 7, false, 3}, Case{130, 96, 32, false, 1},
                          Case{130, 97, 48, true, 3}}) {
        SCOPED_TRACE(std::to_string(k.width) + "x" + std::to_string(k.height) + " strips of " +
                     std::to_string(k.stripRows) + (k.fullFloat ? " float" : " half") + ", threads " +
                     std::to_string(k.threads));
        const fs::path path = dir / "probe.exr";
        writeProbeImage(path, k.width, k.height, k.stripRows, k.fullFloat, k.threads);
        expectProbeImage(path, k.width, k.height, k.fullFloat);
    }
    fs::remove_all(dir);
}

// A wide image is written in 1-line blocks (ZIPS), whose buffers do not grow 16 lines at a time
// with the width (exr_writer.hpp), and reads back the same; a narrow one keeps 16-line ZIP blocks.
TEST(ExrWriter, WideImagesUseOneLineBlocksAndReadBackTheSame) {
    const fs::path dir = fs::temp_directory_path() / ("fraktal_exr_wide_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const fs::path path = dir / "wide.exr";
    writeProbeImage(path, kWideExrWidth, 40, 32, false, 3);
    expectProbeImage(path, kWideExrWidth, 40, false);
    EXPECT_EQ(Imf::InputFile(path.c_str()).header().compression(), Imf::ZIPS_COMPRESSION);
    writeProbeImage(path, kWideExrWidth - 1, 20, 16, false, 2);
    EXPECT_EQ(Imf::InputFile(path.c_str()).header().compression(), Imf::ZIP_COMPRESSION);
    // The writer's block buffers: 16 lines below the threshold, 1 from it, so the wider image's
    // buffers are the smaller.
    EXPECT_EQ(exrWriterBufferBytes(kWideExrWidth, false, 4), 2LL * 4 * 3 * kWideExrWidth * 30);
    EXPECT_GT(exrWriterBufferBytes(kWideExrWidth - 1, false, 4), exrWriterBufferBytes(2 * kWideExrWidth, false, 4));
    EXPECT_EQ(exrRawBytesPerPixel(true), 13 * 4);
    fs::remove_all(dir);
}

TEST(ExrWriter, StripsOutOfOrderAreRefused) {
    const fs::path path = fs::temp_directory_path() / ("fraktal_exr_order_" + std::to_string(::getpid()) + ".exr");
    {
        ExrStripWriter writer(path, 8, 32, false, ExrMetadata{});
        ImageStrip strip;
        strip.resize(8, 16, 16);
        EXPECT_THROW(writer.write(strip), std::logic_error);
        EXPECT_THROW(writer.close(), std::logic_error);
    }
    fs::remove(path);
}

// The F16C path (when the CPU has it) and Imath's bit-shifting conversion agree bit for bit:
// normals, denormals, ties (round to nearest even), overflow to infinity, NaN, signed zero.
TEST(ExrWriter, FastHalfConversionRoundsLikeImath) {
    std::vector<float> values = {0.0f,
                                 -0.0f,
                                 1.0f,
                                 -1.0f,
                                 65504.0f,
                                 65520.0f,
                                 1e30f,
                                 -1e30f,
                                 5.96e-8f,
                                 2.98e-8f,
                                 6.1e-5f,
                                 1.0f + 1.0f / 2048.0f,
                                 1.0f + 3.0f / 2048.0f,  // ties to even
                                 std::numeric_limits<float>::infinity(),
                                 -std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::denorm_min()};
    std::mt19937 rng(7);
    std::uniform_int_distribution<uint32_t> bits;
    for (int i = 0; i < 100000; ++i) {
        const uint32_t b = bits(rng);
        float f;
        std::memcpy(&f, &b, sizeof f);
        if (!std::isnan(f)) values.push_back(f);
        values.push_back(std::ldexp(float(i % 4096) / 4096.0f, i % 40 - 30));
    }
    std::vector<half> fast(values.size()), portable(values.size());
    convertFloatsToHalf(values, fast, HalfConversion::Fastest);
    convertFloatsToHalf(values, portable, HalfConversion::Portable);
    for (size_t i = 0; i < values.size(); ++i) ASSERT_EQ(fast[i].bits(), portable[i].bits()) << "value " << values[i];
    // NaN stays NaN.
    std::vector<float> nan = {std::numeric_limits<float>::quiet_NaN()};
    std::vector<half> out(1);
    convertFloatsToHalf(nan, out);
    EXPECT_TRUE(out[0].isNan());
}

}  // namespace
}  // namespace fraktal
