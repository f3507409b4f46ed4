// A whole still: strips of tiles through the GL renderer into the EXR (and the PNG preview),
// with progress and cancellation. Memory is bounded by one strip plus the 8-bit preview.
#pragma once

#include <atomic>
#include <filesystem>
#include <functional>
#include <optional>
#include <stdexcept>

#include "core/color/color_pipeline.hpp"
#include "core/preset.hpp"

namespace fraktal {

class RenderCancelled : public std::runtime_error {
   public:
    RenderCancelled() : std::runtime_error("render cancelled") {}
};

struct StillProgress {
    int tilesDone = 0;
    int tilesTotal = 0;
    double secondsElapsed = 0.0;
};

// Biggest preview the PNG path takes (it holds 3 bytes per pixel in memory).
inline constexpr long long kMaxPngPixels = 1LL << 28;
// Biggest image at all (EXR rows are streamed; this keeps the strip of a pathological aspect sane).
inline constexpr long long kMaxImagePixels = 1LL << 32;
// Adaptive sampling's default tolerance (shaders/still.frag); bench/stills measures its error.
inline constexpr double kDefaultAdaptiveTolerance = 0.01;

struct StillJob {
    Preset preset;  // preset.render holds the size, spp and colour settings actually used
    std::filesystem::path exr;
    std::optional<std::filesystem::path> png;
    bool fullFloat = false;
    int tileSize = 256;
    std::function<void(const StillProgress&)> onProgress;  // after every tile
    const std::atomic<bool>* cancel = nullptr;             // polled between tiles
    // Part `partIndex` (0-based) of `partCount` horizontal bands of the image (`fraktal render
    // --part i/n`), for `fraktal merge`; 1: the whole image. Every pixel's samples depend only
    // on its image position, so merged parts equal a whole render.
    int partIndex = 0;
    int partCount = 1;
    // Spread of sqrt(colour) under which a pixel stops sampling (shaders/still.frag; 0: all spp).
    double adaptiveTolerance = kDefaultAdaptiveTolerance;
    long long memoryLimitBytes = 0;  // 0: the memory available when the job is checked
    // The disk space the outputs may take must be free where they are written (estimateStillDiskBytes);
    // diskLimitBytes stands in for the free space when > 0 (tests), checkDisk = false skips it.
    bool checkDisk = true;
    long long diskLimitBytes = 0;
};

// Rows [first, end) of part `index` of `count` of an image `height` rows tall.
std::pair<int, int> partRows(int height, int index, int count);

// Peak memory of renderStillJob for `job`, from the buffers it allocates (one strip of floats and
// its half copies, the PNG preview, the GL tile targets and their read-back) plus the process's
// own base (the GL driver and libraries), known before anything is allocated.
long long estimateStillMemoryBytes(const StillJob& job);
// MemAvailable of /proc/meminfo, else the physical memory.
long long availableMemoryBytes();
// The most disk space the job's EXR (and PNG preview) can take: every channel uncompressed plus
// the header and the block offsets, which compression only ever reduces (a fractal's EXR came to
// 21-55 % of it: 2048x1152 Mandelbox to 256-row Menger bands, bench/stills/README.md). Known before anything is
// rendered.
long long estimateStillDiskBytes(const StillJob& job);

// Checks sizes, outputs and colour settings before any rendering, so that bad input fails fast
// and nothing is touched; throws std::runtime_error saying what is wrong.
void validateStillJob(const StillJob& job, const ColorPipeline& color);

// Renders and writes the files atomically (an existing file is replaced only at the very end,
// by a complete one). Needs a current GL context. Throws RenderCancelled when `cancel` was set:
// then nothing is written.
void renderStillJob(const StillJob& job, const ColorPipeline& color);

}  // namespace fraktal
