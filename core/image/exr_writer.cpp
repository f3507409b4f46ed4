#include "core/image/exr_writer.hpp"

#include <Iex.h>
#include <ImfChannelList.h>
#include <ImfFloatAttribute.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <ImfThreading.h>
#include <half.h>
#if defined(__x86_64__) && defined(__GNUC__)
#include <cpuid.h>
#include <immintrin.h>
#endif

#include <algorithm>
#include <glm/gtc/type_ptr.hpp>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

namespace fraktal {

namespace {

constexpr int kRgba = 0, kNormalDepth = 1, kAlbedoAO = 2, kStats = 3;  // ImageStrip::buffers() order
constexpr ExrChannelSource kChannels[] = {
    {"R", kRgba, 0, false},
    {"G", kRgba, 1, false},
    {"B", kRgba, 2, false},
    {"A", kRgba, 3, false},
    {"Z", kNormalDepth, 3, true},
    {"N.x", kNormalDepth, 0, false},
    {"N.y", kNormalDepth, 1, false},
    {"N.z", kNormalDepth, 2, false},
    {"albedo.R", kAlbedoAO, 0, false},
    {"albedo.G", kAlbedoAO, 1, false},
    {"albedo.B", kAlbedoAO, 2, false},
    {"AO", kAlbedoAO, 3, false},
    {"steps", kStats, 1, true},
};

// Float to half over a whole buffer, rounding to nearest even like Imath's half(float). Imath
// converts one value at a time with bit shifts (~2.5 ns a value here) unless the whole program is
// built for F16C; 8192x8192 has 800 M values to convert, so the F16C instruction (8 values at a
// time, same rounding) is used whenever the CPU has it.
#if defined(__x86_64__) && defined(__GNUC__)
__attribute__((target("avx,f16c"))) void convertToHalfF16C(const float* src, uint16_t* dst, size_t n) {
    size_t i = 0;
    for (; i + 8 <= n; i += 8)
        _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + i),
                         _mm256_cvtps_ph(_mm256_loadu_ps(src + i), _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC));
    for (; i < n; ++i) dst[i] = imath_float_to_half(src[i]);
}

// AVX (with the OS saving its registers, which __builtin_cpu_supports checks) and F16C (CPUID
// leaf 1, ECX bit 29; clang 14's __builtin_cpu_supports does not know "f16c").
bool cpuHasF16C() {
    unsigned eax = 0, ebx = 0, ecx = 0, edx = 0;
    return __builtin_cpu_supports("avx") && __get_cpuid(1, &eax, &ebx, &ecx, &edx) && (ecx & bit_F16C) != 0;
}
#endif

}  // namespace

void convertFloatsToHalf(std::span<const float> src, std::span<half> dst, HalfConversion how) {
    if (src.size() != dst.size()) throw std::logic_error("convertFloatsToHalf: sizes differ");
#if defined(__x86_64__) && defined(__GNUC__)
    if (how == HalfConversion::Fastest && cpuHasF16C()) {
        static_assert(sizeof(half) == sizeof(uint16_t));
        convertToHalfF16C(src.data(), reinterpret_cast<uint16_t*>(dst.data()), src.size());
        return;
    }
#endif
    (void)how;
    for (size_t i = 0; i < src.size(); ++i) dst[i].setBits(imath_float_to_half(src[i]));
}

namespace {

Imath::M44f worldToCamera(const Camera& camera) {
    const glm::dmat4 m = glm::inverse(camera.worldFromCamera());
    // OpenEXR's matrices are row-vector convention (v * M): the transpose of GLM's column-vector one,
    // whose memory layout (column-major) reads the same as Imath's row-major transpose.
    Imath::M44f r;
    for (int col = 0; col < 4; ++col)
        for (int row = 0; row < 4; ++row) r[col][row] = float(m[col][row]);
    return r;
}

}  // namespace

int exrBlockRows(int width) { return width >= kWideExrWidth ? 1 : 16; }

long long exrRawBytesPerPixel(bool fullFloat) {
    long long bytes = 0;
    for (const ExrChannelSource& c : kChannels) bytes += c.alwaysFloat || fullFloat ? 4 : 2;
    return bytes;
}

int exrCompressionThreads(int compressionThreads) {
    return compressionThreads > 0 ? compressionThreads : int(std::max(1u, std::thread::hardware_concurrency()));
}

long long exrWriterBufferBytes(int width, bool fullFloat, int compressionThreads) {
    const long long blockBytes = (long long)exrBlockRows(width) * width * exrRawBytesPerPixel(fullFloat);
    return 2LL * exrCompressionThreads(compressionThreads) * 3 * blockBytes;
}

ExrStripWriter::ExrStripWriter(const std::filesystem::path& path, int width, int height, bool fullFloat,
                               const ExrMetadata& meta, int compressionThreads, int firstRow, int rowCount)
    : path_(path),
      width_(width),
      height_(height),
      fullFloat_(fullFloat),
      nextRow_(firstRow),
      endRow_(rowCount < 0 ? height : firstRow + rowCount) {
    if (firstRow < 0 || endRow_ > height || endRow_ <= firstRow)
        throw std::logic_error("ExrStripWriter: rows outside the image");
    Imf::Header header(Imath::Box2i(Imath::V2i(0, 0), Imath::V2i(width - 1, height - 1)),
                       Imath::Box2i(Imath::V2i(0, firstRow), Imath::V2i(width - 1, endRow_ - 1)));
    header.compression() = exrBlockRows(width) == 1 ? Imf::ZIPS_COMPRESSION : Imf::ZIP_COMPRESSION;
    // zlib level 1 instead of OpenEXR's default 4: lossless either way; measured with
    // bench/stills/exr_write.sh it takes 1.25x (a noisy Mandelbulb) to 1.8x (a mostly empty frame)
    // less CPU for files 3 % to 17 % larger (bench/README.md, Stills).
    header.zipCompressionLevel() = 1;
    header.lineOrder() = Imf::INCREASING_Y;
    for (const ExrChannelSource& c : kChannels)
        header.channels().insert(c.name, Imf::Channel(c.alwaysFloat || fullFloat ? Imf::FLOAT : Imf::HALF));
    if (meta.chromaticities) {
        const auto& xy = meta.chromaticities->xy;
        Imf::addChromaticities(header, Imf::Chromaticities(Imath::V2f(float(xy[0].x), float(xy[0].y)),
                                                           Imath::V2f(float(xy[1].x), float(xy[1].y)),
                                                           Imath::V2f(float(xy[2].x), float(xy[2].y)),
                                                           Imath::V2f(float(xy[3].x), float(xy[3].y))));
    }
    Imf::addWorldToCamera(header, worldToCamera(meta.camera));
    header.insert(kExrFovAttribute, Imf::FloatAttribute(float(meta.camera.fovY)));
    header.insert(kExrSppAttribute, Imf::IntAttribute(meta.spp));
    header.insert(kExrWorkingSpaceAttribute, Imf::StringAttribute(meta.workingSpace));
    header.insert(kExrPresetAttribute, Imf::StringAttribute(meta.presetJson));
    header.insert("software", Imf::StringAttribute("fraktal"));
    if (!meta.part.empty()) header.insert(kExrPartAttribute, Imf::StringAttribute(meta.part));
    // ZIP compresses each block of 16 scanlines independently; OpenEXR runs those blocks on its
    // global thread pool (the pool is OpenEXR's own process-wide state; it has no threads unless
    // asked). Without it, compression is single-threaded and dominates large renders.
    const int threads = exrCompressionThreads(compressionThreads);
    if (Imf::globalThreadCount() < threads) Imf::setGlobalThreadCount(threads);
    try {
        file_ = std::make_unique<Imf::OutputFile>(path.c_str(), header, threads);
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": cannot create EXR: " + e.what());
    }
}

ExrStripWriter::~ExrStripWriter() = default;

void ExrStripWriter::write(const ImageStrip& strip) {
    if (!file_) throw std::logic_error("ExrStripWriter::write after close");
    if (strip.y0 != nextRow_ || strip.width != width_ || strip.y0 + strip.rows > endRow_)
        throw std::logic_error("ExrStripWriter: strips must cover the rows in order");
    // Slices point into interleaved buffers (4 values per pixel) instead of planar copies:
    // OpenEXR de-interleaves while it fills each line buffer, inside its compression tasks on the
    // thread pool. Float channels read the strip itself; half channels read an interleaved half
    // copy of their buffer, converted in one straight pass (OutputFile does not convert types).
    const auto buffers = strip.buffers();
    bool converted[4] = {false, false, false, false};
    Imf::FrameBuffer fb;
    for (const ExrChannelSource& c : kChannels) {
        const Imath::V2i origin(0, strip.y0);
        if (c.alwaysFloat || fullFloat_) {
            fb.insert(c.name, Imf::Slice::Make(Imf::FLOAT, buffers[c.buffer]->data() + c.component, origin, strip.width,
                                               strip.rows, 4 * sizeof(float), 4 * sizeof(float) * size_t(strip.width)));
            continue;
        }
        std::vector<half>& halves = halfBuffers_[size_t(c.buffer)];
        if (!converted[c.buffer]) {
            halves.resize(buffers[c.buffer]->size());
            convertFloatsToHalf(*buffers[c.buffer], halves);
        }
        converted[c.buffer] = true;
        fb.insert(c.name, Imf::Slice::Make(Imf::HALF, halves.data() + c.component, origin, strip.width, strip.rows,
                                           4 * sizeof(half), 4 * sizeof(half) * size_t(strip.width)));
    }
    try {
        file_->setFrameBuffer(fb);
        file_->writePixels(strip.rows);
    } catch (const std::exception& e) {
        throw std::runtime_error(path_.string() + ": writing EXR rows failed: " + e.what());
    }
    nextRow_ += strip.rows;
}

void ExrStripWriter::close() {
    if (nextRow_ != endRow_) throw std::logic_error("ExrStripWriter::close before every row was written");
    try {
        file_.reset();  // the destructor writes the line offset table
    } catch (const std::exception& e) {
        throw std::runtime_error(path_.string() + ": closing EXR failed: " + e.what());
    }
}

std::span<const ExrChannelSource> exrStripChannels() { return kChannels; }

std::string readExrPreset(const std::filesystem::path& path) {
    try {
        Imf::InputFile in(path.c_str());
        const auto* a = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPresetAttribute);
        if (!a)
            throw std::runtime_error(path.string() + ": EXR has no embedded fraktal preset (attribute " +
                                     kExrPresetAttribute + ")");
        return a->value();
    } catch (const Iex::BaseExc& e) {
        throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
    }
}

std::string describeExr(const std::filesystem::path& path) {
    std::ostringstream s;
    try {
        Imf::InputFile in(path.c_str());
        const Imf::Header& h = in.header();
        const Imath::Box2i dw = h.dataWindow();
        s << path.string() << ": " << (dw.max.x - dw.min.x + 1) << " x " << (dw.max.y - dw.min.y + 1) << "\n";
        s << "channels:";
        for (auto c = h.channels().begin(); c != h.channels().end(); ++c)
            s << " " << c.name()
              << (c.channel().type == Imf::HALF    ? "(half)"
                  : c.channel().type == Imf::FLOAT ? "(float)"
                                                   : "(uint)");
        s << "\n";
        if (Imf::hasChromaticities(h)) {
            const Imf::Chromaticities& c = Imf::chromaticities(h);
            s << "chromaticities: red " << c.red << " green " << c.green << " blue " << c.blue << " white " << c.white
              << "\n";
        }
        if (auto* a = h.findTypedAttribute<Imf::StringAttribute>(kExrWorkingSpaceAttribute))
            s << "working space: " << a->value() << "\n";
        if (auto* a = h.findTypedAttribute<Imf::IntAttribute>(kExrSppAttribute))
            s << "samples per pixel: " << a->value() << "\n";
        if (auto* a = h.findTypedAttribute<Imf::StringAttribute>(kExrPresetAttribute))
            s << "preset (" << kExrPresetAttribute << "):\n" << a->value();
        else
            s << "no embedded fraktal preset\n";
    } catch (const Iex::BaseExc& e) {
        throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
    }
    return s.str();
}

}  // namespace fraktal
