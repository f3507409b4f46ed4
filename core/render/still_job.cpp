#include "core/render/still_job.hpp"

#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/image/exr_writer.hpp"
#include "core/image/png_writer.hpp"
#include "core/render/still_renderer.hpp"
#include "core/render/tiles.hpp"

namespace fraktal {

namespace {

bool hasExtension(const std::filesystem::path& p, const char* ext) {
    std::string e = p.extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e == ext;
}

std::string megabytes(long long bytes) { return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MB"; }

std::string gigabytes(long long bytes) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f GB", double(bytes) / 1e9);
    return text;
}

// Free space for a new file at `file` (its folder's file system); -1 when it cannot be read.
long long freeBytesFor(const std::filesystem::path& file) {
    std::error_code ec;
    const std::filesystem::path folder = std::filesystem::absolute(file, ec).parent_path();
    const std::filesystem::space_info space = std::filesystem::space(folder, ec);
    return ec ? -1 : (long long)space.available;
}

// The GL driver (llvmpipe's own tile buffers), compiled shaders and libraries: measured peaks were
// 125 MB (1280x720) to 170 MB (16384 wide) above the buffers counted below.
constexpr long long kProcessBaseBytes = 176LL << 20;

}  // namespace

std::pair<int, int> partRows(int height, int index, int count) {
    return {int((long long)height * index / count), int((long long)height * (index + 1) / count)};
}

long long estimateStillMemoryBytes(const StillJob& job) {
    const RenderSettings& r = job.preset.render;
    const long long tile = std::min(job.tileSize, std::max(r.width, r.height));
    const long long stripPixels = (long long)r.width * stillStripRows(r.width, int(tile));
    const long long floatsPerPixel = 4 * 4;  // ImageStrip: four RGBA float buffers
    const long long stripBytes = stripPixels * floatsPerPixel * (long long)(sizeof(float) + sizeof(uint16_t));
    const long long previewBytes = job.png ? (long long)r.width * r.height * 3 : 0;
    const long long tileBytes = tile * tile * floatsPerPixel * (long long)sizeof(float) + tile * tile * 4 * 4;
    return kProcessBaseBytes + stripBytes + previewBytes + tileBytes + exrWriterBufferBytes(r.width, job.fullFloat, 0);
}

long long estimateStillDiskBytes(const StillJob& job) {
    const RenderSettings& r = job.preset.render;
    const auto [firstRow, endRow] = partRows(r.height, job.partIndex, job.partCount);
    const long long rows = endRow - firstRow;
    const long long blocks = (rows + exrBlockRows(r.width) - 1) / exrBlockRows(r.width);
    // Per block: its offset in the table and its own y and size words; the header, with the
    // embedded preset (a few KB), within 1 MB.
    const long long exr = rows * r.width * exrRawBytesPerPixel(job.fullFloat) + blocks * 16 + (1 << 20);
    // An 8-bit RGB PNG: the raw rows, each with its filter byte, and zlib's worst case.
    const long long png = job.png ? (long long)r.height * (3LL * r.width + 1) * 1001 / 1000 + (64 << 10) : 0;
    return exr + png;
}

long long availableMemoryBytes() {
    std::ifstream meminfo("/proc/meminfo");
    std::string line;
    while (std::getline(meminfo, line)) {
        long long kb = 0;
        if (std::sscanf(line.c_str(), "MemAvailable: %lld kB", &kb) == 1) return kb * 1024;
    }
    return (long long)sysconf(_SC_PHYS_PAGES) * (long long)sysconf(_SC_PAGE_SIZE);
}

void validateStillJob(const StillJob& job, const ColorPipeline& color) {
    const RenderSettings& r = job.preset.render;
    if (r.width < 1 || r.height < 1 || r.width > kMaxImageSide || r.height > kMaxImageSide)
        throw std::runtime_error("image size " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                                 " is outside 1.." + std::to_string(kMaxImageSide) + " per side");
    if ((long long)r.width * r.height > kMaxImagePixels)
        throw std::runtime_error("image of " + std::to_string((long long)r.width * r.height) + " pixels is too big");
    if (r.spp < 1 || r.spp > kMaxSpp)
        throw std::runtime_error("samples per pixel " + std::to_string(r.spp) + " is outside 1.." +
                                 std::to_string(kMaxSpp));
    if (job.partCount < 1 || job.partCount > r.height || job.partIndex < 0 || job.partIndex >= job.partCount)
        throw std::runtime_error("part " + std::to_string(job.partIndex + 1) + "/" + std::to_string(job.partCount) +
                                 " of an image " + std::to_string(r.height) +
                                 " rows tall: expected 1 <= i <= n <= " + std::to_string(r.height));
    if (job.partCount > 1 && job.png) throw std::runtime_error("a part (--part) has no PNG preview; merge the parts");
    if (job.tileSize < 16 || job.tileSize > 4096) throw std::runtime_error("tile size must be within 16..4096");
    if (!(job.adaptiveTolerance >= 0.0 && job.adaptiveTolerance <= 1.0))
        throw std::runtime_error("adaptive tolerance " + std::to_string(job.adaptiveTolerance) + " is outside 0..1");
    const long long needed = estimateStillMemoryBytes(job);
    const long long limit = job.memoryLimitBytes > 0 ? job.memoryLimitBytes : availableMemoryBytes();
    if (needed > limit)
        throw std::runtime_error("image size " + std::to_string(r.width) + "x" + std::to_string(r.height) +
                                 (job.png ? " with a PNG preview" : "") + " needs an estimated " + megabytes(needed) +
                                 " of memory; " + megabytes(limit) + " is available" +
                                 (job.png ? " (without --png it needs less)" : ""));
    if (job.checkDisk) {
        const long long needed = estimateStillDiskBytes(job);
        const long long free = job.diskLimitBytes > 0 ? job.diskLimitBytes : freeBytesFor(job.exr);
        if (free >= 0 && needed > free)
            throw std::runtime_error(
                job.exr.string() + ": the output may take up to " + gigabytes(needed) +
                " (uncompressed; compressed, fractals measured 21-55 % of that) and its folder's disk has " +
                gigabytes(free) +
                " free; free some space, write elsewhere, render parts (--part i/n) on several disks, or pass "
                "--no-disk-check to try anyway");
    }
    if (!hasExtension(job.exr, ".exr"))
        throw std::runtime_error(job.exr.string() + ": unknown output extension '" + job.exr.extension().string() +
                                 "' (expected .exr; use --png for a preview)");
    AtomicFile checkExr(job.exr);  // throws when the folder is missing or not writable
    if (job.png) {
        if (!hasExtension(*job.png, ".png"))
            throw std::runtime_error(job.png->string() + ": unknown preview extension '" +
                                     job.png->extension().string() + "' (expected .png)");
        if ((long long)r.width * r.height > kMaxPngPixels)
            throw std::runtime_error("a PNG preview is limited to " + std::to_string(kMaxPngPixels) +
                                     " pixels; render the EXR alone at this size");
        AtomicFile checkPng(*job.png);
        if (std::filesystem::absolute(*job.png) == std::filesystem::absolute(job.exr))
            throw std::runtime_error("the EXR and the PNG must be different files");
    }
    color.resolveSpace(r.workingSpace);
    color.checkDisplayView(r.display, r.view);
}

void renderStillJob(const StillJob& job, const ColorPipeline& color) {
    validateStillJob(job, color);
    const Preset& preset = job.preset;
    const RenderSettings& r = preset.render;
    const std::string workingSpace = color.resolveSpace(r.workingSpace);
    const ShadingParams shading = resolveShading(
        preset.shading, r, preset.formula, [&](const vec3& c) { return color.fromLinearRec709(c, workingSpace); });
    const DisplayTransform display(color, workingSpace, r.display, r.view, r.exposure);

    const int tileSize = std::min(job.tileSize, std::max(r.width, r.height));
    gl::StillRenderer renderer(preset.formula, tileSize);
    renderer.setScene(preset.formula, preset.camera, r, shading, job.adaptiveTolerance, preset.lighting.lens);

    AtomicFile exrFile(job.exr);
    ExrMetadata meta;
    meta.presetJson = serializePreset(preset);
    meta.camera = preset.camera;
    meta.spp = r.spp;
    meta.workingSpace = workingSpace;
    meta.chromaticities = color.chromaticities(workingSpace);
    const auto [firstRow, endRow] = partRows(r.height, job.partIndex, job.partCount);
    if (job.partCount > 1) meta.part = std::to_string(job.partIndex + 1) + "/" + std::to_string(job.partCount);
    ExrStripWriter exr(exrFile.tempPath(), r.width, r.height, job.fullFloat, meta, 0, firstRow, endRow - firstRow);
    std::vector<uint8_t> preview;
    if (job.png) preview.resize(size_t(r.width) * size_t(r.height) * 3);

    std::vector<TileRect> strips = stripsOf(r.width, endRow - firstRow, stillStripRows(r.width, tileSize));
    for (TileRect& s : strips) s.y += firstRow;
    StillProgress progress;
    for (const TileRect& s : strips) progress.tilesTotal += int(tilesOf(s, tileSize).size());
    const auto start = std::chrono::steady_clock::now();
    ImageStrip strip;
    for (const TileRect& s : strips) {
        strip.resize(r.width, s.y, s.height);
        for (const TileRect& tile : tilesOf(s, tileSize)) {
            if (job.cancel && job.cancel->load()) throw RenderCancelled();
            renderer.renderTile(tile, strip);
            ++progress.tilesDone;
            progress.secondsElapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (job.onProgress) job.onProgress(progress);
        }
        exr.write(strip);
        if (job.png)
            display.toDisplay8(strip.rgba, std::span(preview).subspan(size_t(s.y) * size_t(r.width) * 3,
                                                                      size_t(s.height) * size_t(r.width) * 3));
    }
    if (job.cancel && job.cancel->load()) throw RenderCancelled();
    exr.close();
    if (job.png) writePngAtomic(*job.png, r.width, r.height, preview);
    exrFile.commit();
}

}  // namespace fraktal
