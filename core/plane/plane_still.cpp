#include "core/plane/plane_still.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfOutputFile.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <half.h>

#include "core/atomic_file.hpp"
#include "core/image/png_writer.hpp"
#include "core/render/still_job.hpp"

namespace fraktal {

mat3 planeWorkingFromRec709(const ColorPipeline& color, const std::string& workingSpace) {
    mat3 m(1.0);
    for (int i = 0; i < 3; ++i) {
        vec3 e(0.0);
        e[i] = 1.0;
        m[i] = color.fromLinearRec709(e, workingSpace);
    }
    return m;
}

namespace {

// One strip of full-width rows in the EXR's channel layout.
struct PlaneStrip {
    int width = 0, rows = 0;
    std::vector<float> rgba, inside, iterations, distance;
    void resize(int w, int r) {
        width = w;
        rows = r;
        rgba.assign(size_t(w) * size_t(r) * 4, 0.0f);
        inside.assign(size_t(w) * size_t(r), 0.0f);
        iterations.assign(size_t(w) * size_t(r), 0.0f);
        distance.assign(size_t(w) * size_t(r), 0.0f);
    }
};

class PlaneExrWriter {
   public:
    PlaneExrWriter(const std::filesystem::path& path, int width, int height, bool fullFloat, const Imf::Header& extra)
        : width_(width), fullFloat_(fullFloat) {
        Imf::Header header = extra;
        header.dataWindow() = header.displayWindow() = Imath::Box2i({0, 0}, {width - 1, height - 1});
        header.compression() = Imf::ZIP_COMPRESSION;
        header.lineOrder() = Imf::INCREASING_Y;
        const Imf::PixelType colour = fullFloat ? Imf::FLOAT : Imf::HALF;
        for (const char* c : {"R", "G", "B", "A", "inside"}) header.channels().insert(c, Imf::Channel(colour));
        // Iteration counts and deep-zoom distances need the range and precision of 32 bits.
        header.channels().insert("iterations", Imf::Channel(Imf::FLOAT));
        header.channels().insert("distance", Imf::Channel(Imf::FLOAT));
        try {
            file_ = std::make_unique<Imf::OutputFile>(path.c_str(), header);
        } catch (const std::exception& e) {
            throw std::runtime_error(path.string() + ": cannot create EXR: " + e.what());
        }
    }

    void write(const PlaneStrip& s, int y0) {
        const size_t n = size_t(s.width) * size_t(s.rows);
        Imf::FrameBuffer fb;
        // Slices address the whole image: shift the base pointer back by y0 rows.
        const ptrdiff_t shift = ptrdiff_t(y0) * width_;
        if (fullFloat_) {
            const char* names[4] = {"R", "G", "B", "A"};
            for (int c = 0; c < 4; ++c)
                fb.insert(names[c],
                          Imf::Slice(Imf::FLOAT, (char*)(s.rgba.data() + c - shift * 4), 16, 16 * size_t(width_)));
            fb.insert("inside", Imf::Slice(Imf::FLOAT, (char*)(s.inside.data() - shift), 4, 4 * size_t(width_)));
        } else {
            halves_.resize(n * 5);
            for (size_t i = 0; i < n * 4; ++i) halves_[i] = half(s.rgba[i]);
            for (size_t i = 0; i < n; ++i) halves_[n * 4 + i] = half(s.inside[i]);
            const char* names[4] = {"R", "G", "B", "A"};
            for (int c = 0; c < 4; ++c)
                fb.insert(names[c],
                          Imf::Slice(Imf::HALF, (char*)(halves_.data() + c - shift * 4), 8, 8 * size_t(width_)));
            fb.insert("inside", Imf::Slice(Imf::HALF, (char*)(halves_.data() + n * 4 - shift), 2, 2 * size_t(width_)));
        }
        fb.insert("iterations", Imf::Slice(Imf::FLOAT, (char*)(s.iterations.data() - shift), 4, 4 * size_t(width_)));
        fb.insert("distance", Imf::Slice(Imf::FLOAT, (char*)(s.distance.data() - shift), 4, 4 * size_t(width_)));
        file_->setFrameBuffer(fb);
        file_->writePixels(s.rows);
    }
    void close() { file_.reset(); }

   private:
    int width_;
    bool fullFloat_;
    std::vector<half> halves_;
    std::unique_ptr<Imf::OutputFile> file_;
};

}  // namespace

std::optional<std::string> readExrPlanePreset(const std::filesystem::path& path) {
    try {
        Imf::InputFile in(path.c_str());
        const auto* text = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPlanePresetAttribute);
        if (!text) return std::nullopt;
        return text->value();
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
    }
}

void validatePlaneStillJob(const PlaneStillJob& job, const ColorPipeline& color) {
    // The 3D still's checks cover everything but the scene: size, spp, extensions, folders, colour.
    StillJob still;
    still.preset.render = job.preset.render;
    still.exr = job.exr;
    still.png = job.png;
    still.tileSize = std::clamp(job.tileSize, 16, 4096);
    validateStillJob(still, color);
    if (job.tileSize < 16 || job.tileSize > 4096) throw std::runtime_error("tile size must be within 16..4096");
}

std::vector<std::string> renderPlaneStill(const PlaneStillJob& job, const ColorPipeline& color) {
    validatePlaneStillJob(job, color);
    const PlanePreset& p = job.preset;
    const RenderSettings& r = p.render;
    const std::string workingSpace = color.resolveSpace(r.workingSpace);
    const mat3 toWorking = planeWorkingFromRec709(color, r.workingSpace);

    PlaneRenderer renderer;
    renderer.prepare(p.formula, job.precision);
    PlaneTarget target;

    AtomicFile exrFile(job.exr);
    Imf::Header header;
    if (auto xy = color.chromaticities(workingSpace))
        Imf::addChromaticities(header, Imf::Chromaticities(Imath::V2f(float(xy->xy[0].x), float(xy->xy[0].y)),
                                                           Imath::V2f(float(xy->xy[1].x), float(xy->xy[1].y)),
                                                           Imath::V2f(float(xy->xy[2].x), float(xy->xy[2].y)),
                                                           Imath::V2f(float(xy->xy[3].x), float(xy->xy[3].y))));
    header.insert(kExrPlanePresetAttribute, Imf::StringAttribute(serializePlanePreset(p)));
    header.insert("fraktal.workingSpace", Imf::StringAttribute(workingSpace));
    header.insert("fraktal.spp", Imf::IntAttribute(r.spp));
    header.insert("software", Imf::StringAttribute("fraktal"));
    PlaneExrWriter exr(exrFile.tempPath(), r.width, r.height, job.fullFloat, header);

    std::optional<DisplayTransform> display;
    std::vector<uint8_t> preview;
    if (job.png) {
        display.emplace(color, r.workingSpace, r.display, r.view, r.exposure);
        preview.resize(size_t(r.width) * size_t(r.height) * 3);
    }

    const int tile = job.tileSize;
    const int tilesX = (r.width + tile - 1) / tile, tilesY = (r.height + tile - 1) / tile;
    int done = 0;
    PlaneStrip strip;
    for (int ty = 0; ty < tilesY; ++ty) {
        const int y0 = ty * tile, rows = std::min(tile, r.height - y0);
        strip.resize(r.width, rows);
        for (int tx = 0; tx < tilesX; ++tx) {
            if (job.cancel && job.cancel->load()) throw RenderCancelled();
            const PlaneTile t{r.width, r.height, tx * tile, y0, std::min(tile, r.width - tx * tile), rows};
            renderer.render(p.formula, p.colouring, p.view, t, target, 0, r.spp, false);
            const PlaneTileData d = readPlaneTarget(target);
            for (int y = 0; y < t.height; ++y)
                for (int x = 0; x < t.width; ++x) {
                    const size_t o = size_t(y) * size_t(r.width) + size_t(t.x0 + x);
                    const vec3 rgb = toWorking * d.meanColour(x, y);
                    for (int c = 0; c < 3; ++c) strip.rgba[o * 4 + size_t(c)] = float(rgb[c]);
                    strip.rgba[o * 4 + 3] = 1.0f;  // opaque: the inside colour is part of the image
                    strip.inside[o] = float(d.insideFraction(x, y));
                    strip.iterations[o] = float(d.meanIterations(x, y));
                    strip.distance[o] = float(d.meanDistance(x, y));
                }
            if (job.onProgress) job.onProgress(++done, tilesX * tilesY);
        }
        exr.write(strip, y0);
        if (display)
            display->toDisplay8(strip.rgba, std::span(preview).subspan(size_t(y0) * size_t(r.width) * 3,
                                                                       size_t(rows) * size_t(r.width) * 3));
    }
    exr.close();
    exrFile.commit();
    if (job.png) writePngAtomic(*job.png, r.width, r.height, preview);
    return renderer.warnings();
}

}  // namespace fraktal
