// Streaming scanline EXR output with the AOVs a compositor expects: R G B A, Z, N.x N.y N.z,
// albedo.R albedo.G albedo.B, AO, steps. Colour and AOVs are half float by default (32-bit on
// request); Z and steps are always 32-bit (depth needs the range). Rows are written strip by strip
// in increasing y, so memory stays bounded for any image size.
#pragma once

#include <ImfOutputFile.h>
#include <half.h>

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/camera.hpp"
#include "core/color/color_pipeline.hpp"
#include "core/image/image_strip.hpp"

namespace fraktal {

// Header attribute names (read back by `fraktal info` and `fraktal render OUT.exr`).
inline constexpr const char* kExrPresetAttribute = "fraktal.preset";
inline constexpr const char* kExrSppAttribute = "fraktal.spp";
inline constexpr const char* kExrWorkingSpaceAttribute = "fraktal.workingSpace";
inline constexpr const char* kExrFovAttribute = "fraktal.camera.fovY";
// "i/n" in the part of a still rendered with `fraktal render --part i/n` (absent in a whole image).
inline constexpr const char* kExrPartAttribute = "fraktal.part";

struct ExrMetadata {
    std::string presetJson;  // the whole preset, as written by serializePreset
    Camera camera;
    int spp = 1;
    std::string workingSpace;
    std::optional<Chromaticities> chromaticities;
    std::string part;  // kExrPartAttribute; empty: a whole image
};

// Where each EXR channel comes from: which of the strip's four interleaved buffers (in
// ImageStrip::buffers() order), which component, and whether it is always 32-bit float.
struct ExrChannelSource {
    const char* name;
    int buffer;
    int component;
    bool alwaysFloat;
};
// The channels fraktal writes, in this order: R G B A, Z, N.x N.y N.z, albedo.R/G/B, AO, steps.
std::span<const ExrChannelSource> exrStripChannels();

// Scanlines per compressed block of a still's EXR `width` pixels wide: 16 (ZIP) below
// kWideExrWidth, 1 (ZIPS) from there. OpenEXR keeps two blocks per compression thread in flight,
// each about three times its raw size (the lines, zlib's output and its scratch), so 16-line blocks
// grow with the width: at 32768 wide and 16 threads they held 844 MB against 306 MB for 1-line
// blocks (bench/stills/exr_write.cpp). A wide image's line already fills zlib's window many times
// over, so 1-line blocks compress as well there (+0.3 % at 16384, -0.03 % at 32768; +2.8 % at
// 1280, hence the threshold), and a strip holds 64-128 blocks to spread over the threads, where
// 16-line blocks gave 4 at 32768 wide (measured in bench/stills/README.md).
inline constexpr int kWideExrWidth = 8192;
int exrBlockRows(int width);
// Bytes per pixel of the still's channels, uncompressed (the most a compressed block can take).
long long exrRawBytesPerPixel(bool fullFloat);
// OpenEXR's memory for the blocks in flight while writing: two per compression thread.
long long exrWriterBufferBytes(int width, bool fullFloat, int compressionThreads);
// The compression threads of `compressionThreads` (0: one per core).
int exrCompressionThreads(int compressionThreads);

class ExrStripWriter {
   public:
    // Opens `path` for writing (the caller passes an AtomicFile's temporary path). Compression
    // runs on `compressionThreads` threads (0: one per core).
    // With `rowCount` >= 0, the file holds only rows [firstRow, firstRow + rowCount) of the
    // width x height image (its data window; a part to be merged).
    ExrStripWriter(const std::filesystem::path& path, int width, int height, bool fullFloat, const ExrMetadata& meta,
                   int compressionThreads = 0, int firstRow = 0, int rowCount = -1);
    ~ExrStripWriter();
    // Strips must arrive in order, covering every row exactly once. Strips of a multiple of
    // exrBlockRows(width) rows let OpenEXR compress whole blocks in parallel within the call.
    void write(const ImageStrip& strip);
    // Flushes and closes the file; throws on failure.
    void close();

   private:
    std::filesystem::path path_;
    int width_, height_;
    bool fullFloat_;
    int nextRow_ = 0;
    int endRow_ = 0;
    std::unique_ptr<Imf::OutputFile> file_;
    // Interleaved half copies of the strip's buffers, reused from strip to strip.
    std::array<std::vector<half>, 4> halfBuffers_;
};

// Float to half (round to nearest even, as Imath's half(float)). Fastest uses the CPU's F16C
// instruction when it has one; Portable is Imath's per-value conversion (the tests compare them).
enum class HalfConversion { Fastest, Portable };
void convertFloatsToHalf(std::span<const float> src, std::span<half> dst, HalfConversion how = HalfConversion::Fastest);

// The preset embedded in an EXR written by fraktal; throws naming the file when there is none.
std::string readExrPreset(const std::filesystem::path& path);
// A human-readable listing of an EXR's size, channels and fraktal attributes.
std::string describeExr(const std::filesystem::path& path);

}  // namespace fraktal
