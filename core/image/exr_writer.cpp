#include "core/image/exr_writer.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfIntAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfStandardAttributes.h>
#include <ImfStringAttribute.h>
#include <Iex.h>
#include <half.h>

#include <glm/gtc/type_ptr.hpp>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace fraktal {

namespace {

// Channel name, which strip buffer and component it comes from, and whether it is always float.
struct ChannelSource {
    const char* name;
    std::vector<float> ImageStrip::*buffer;
    int component;
    bool alwaysFloat;
};

constexpr ChannelSource kChannels[] = {
    {"R", &ImageStrip::rgba, 0, false},           {"G", &ImageStrip::rgba, 1, false},
    {"B", &ImageStrip::rgba, 2, false},           {"A", &ImageStrip::rgba, 3, false},
    {"Z", &ImageStrip::normalDepth, 3, true},     {"N.x", &ImageStrip::normalDepth, 0, false},
    {"N.y", &ImageStrip::normalDepth, 1, false},  {"N.z", &ImageStrip::normalDepth, 2, false},
    {"albedo.R", &ImageStrip::albedoAO, 0, false}, {"albedo.G", &ImageStrip::albedoAO, 1, false},
    {"albedo.B", &ImageStrip::albedoAO, 2, false}, {"AO", &ImageStrip::albedoAO, 3, false},
    {"steps", &ImageStrip::stats, 1, true},
};

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

ExrStripWriter::ExrStripWriter(const std::filesystem::path& path, int width, int height, bool fullFloat,
                               const ExrMetadata& meta)
    : path_(path), width_(width), height_(height), fullFloat_(fullFloat) {
    Imf::Header header(width, height);
    header.compression() = Imf::ZIP_COMPRESSION;
    header.lineOrder() = Imf::INCREASING_Y;
    for (const ChannelSource& c : kChannels)
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
    try {
        file_ = std::make_unique<Imf::OutputFile>(path.c_str(), header);
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": cannot create EXR: " + e.what());
    }
}

ExrStripWriter::~ExrStripWriter() = default;

void ExrStripWriter::write(const ImageStrip& strip) {
    if (!file_) throw std::logic_error("ExrStripWriter::write after close");
    if (strip.y0 != nextRow_ || strip.width != width_ || strip.y0 + strip.rows > height_)
        throw std::logic_error("ExrStripWriter: strips must cover the rows in order");
    const size_t pixels = size_t(strip.width) * size_t(strip.rows);
    // Planar copies: EXR wants one slice per channel, in half or float.
    std::vector<std::vector<float>> floats;
    std::vector<std::vector<half>> halves;
    floats.reserve(std::size(kChannels));
    halves.reserve(std::size(kChannels));
    Imf::FrameBuffer fb;
    for (const ChannelSource& c : kChannels) {
        const std::vector<float>& src = strip.*(c.buffer);
        const Imath::V2i origin(0, strip.y0);
        if (c.alwaysFloat || fullFloat_) {
            std::vector<float>& dst = floats.emplace_back(pixels);
            for (size_t i = 0; i < pixels; ++i) dst[i] = src[4 * i + size_t(c.component)];
            fb.insert(c.name, Imf::Slice::Make(Imf::FLOAT, dst.data(), origin, strip.width, strip.rows));
        } else {
            std::vector<half>& dst = halves.emplace_back(pixels);
            for (size_t i = 0; i < pixels; ++i) dst[i] = half(src[4 * i + size_t(c.component)]);
            fb.insert(c.name, Imf::Slice::Make(Imf::HALF, dst.data(), origin, strip.width, strip.rows));
        }
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
    if (nextRow_ != height_) throw std::logic_error("ExrStripWriter::close before every row was written");
    try {
        file_.reset();  // the destructor writes the line offset table
    } catch (const std::exception& e) {
        throw std::runtime_error(path_.string() + ": closing EXR failed: " + e.what());
    }
}

std::string readExrPreset(const std::filesystem::path& path) {
    try {
        Imf::InputFile in(path.c_str());
        const auto* a = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPresetAttribute);
        if (!a) throw std::runtime_error(path.string() + ": EXR has no embedded fraktal preset (attribute " +
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
            s << " " << c.name() << (c.channel().type == Imf::HALF ? "(half)" : c.channel().type == Imf::FLOAT ? "(float)" : "(uint)");
        s << "\n";
        if (Imf::hasChromaticities(h)) {
            const Imf::Chromaticities& c = Imf::chromaticities(h);
            s << "chromaticities: red " << c.red << " green " << c.green << " blue " << c.blue << " white " << c.white << "\n";
        }
        if (auto* a = h.findTypedAttribute<Imf::StringAttribute>(kExrWorkingSpaceAttribute))
            s << "working space: " << a->value() << "\n";
        if (auto* a = h.findTypedAttribute<Imf::IntAttribute>(kExrSppAttribute)) s << "samples per pixel: " << a->value() << "\n";
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
