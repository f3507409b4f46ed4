#include "core/image/exr_merge.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfOutputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "core/atomic_file.hpp"
#include "core/image/exr_writer.hpp"

namespace fraktal {

namespace {

struct Part {
    std::filesystem::path path;
    std::unique_ptr<Imf::InputFile> file;
    Imath::Box2i rows() const { return file->header().dataWindow(); }
};

std::string presetOf(const Imf::Header& h) {
    const auto* a = h.findTypedAttribute<Imf::StringAttribute>(kExrPresetAttribute);
    return a ? a->value() : std::string();
}

size_t bytesOf(Imf::PixelType t) { return t == Imf::HALF ? 2 : 4; }

}  // namespace

void mergeExrParts(const std::vector<std::filesystem::path>& paths, const std::filesystem::path& output) {
    if (paths.empty()) throw std::runtime_error("merge: no parts given");
    std::vector<Part> parts;
    for (const auto& path : paths) {
        Part p{path, nullptr};
        try {
            p.file = std::make_unique<Imf::InputFile>(path.c_str());
        } catch (const std::exception& e) {
            throw std::runtime_error(path.string() + ": cannot read EXR: " + e.what());
        }
        if (!p.file->header().findTypedAttribute<Imf::StringAttribute>(kExrPartAttribute))
            throw std::runtime_error(path.string() + ": not a part of a still (no " + std::string(kExrPartAttribute) +
                                     " attribute; render parts with `fraktal render --part i/n`)");
        parts.push_back(std::move(p));
    }
    const Imf::Header& first = parts[0].file->header();
    const Imath::Box2i image = first.displayWindow();
    for (const Part& p : parts) {
        const Imf::Header& h = p.file->header();
        if (h.displayWindow() != image || presetOf(h) != presetOf(first))
            throw std::runtime_error(p.path.string() + ": a part of another image than " + parts[0].path.string() +
                                     " (size or embedded preset differ)");
        bool sameChannels = true;
        for (auto c = first.channels().begin(); c != first.channels().end(); ++c) {
            const Imf::Channel* other = h.channels().findChannel(c.name());
            sameChannels = sameChannels && other && other->type == c.channel().type;
        }
        if (!sameChannels)
            throw std::runtime_error(p.path.string() + ": its channels differ from " + parts[0].path.string());
    }
    std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) { return a.rows().min.y < b.rows().min.y; });
    int nextRow = image.min.y;
    for (const Part& p : parts) {
        if (p.rows().min.y > nextRow)
            throw std::runtime_error("merge: rows " + std::to_string(nextRow) + "-" +
                                     std::to_string(p.rows().min.y - 1) + " are in no part (a part is missing)");
        if (p.rows().min.y < nextRow)
            throw std::runtime_error(p.path.string() + ": its rows overlap another part's (a part given twice?)");
        nextRow = p.rows().max.y + 1;
    }
    if (nextRow != image.max.y + 1)
        throw std::runtime_error("merge: rows " + std::to_string(nextRow) + "-" + std::to_string(image.max.y) +
                                 " are in no part (a part is missing)");

    // The first part's header without its part attribute, built by copying every other
    // attribute: OpenEXR 3.1's Header::erase drops an attribute without deleting it (a leak the
    // sanitizer run reports).
    Imf::Header header;
    for (auto a = first.begin(); a != first.end(); ++a)
        if (std::string_view(a.name()) != kExrPartAttribute) header.insert(a.name(), a.attribute());
    header.dataWindow() = image;
    AtomicFile out(output);
    {
        Imf::OutputFile file(out.tempPath().c_str(), header);
        const int width = image.max.x - image.min.x + 1;
        constexpr int kBandRows = 64;
        std::vector<std::vector<char>> buffers;
        for (const Part& p : parts) {
            for (int y0 = p.rows().min.y; y0 <= p.rows().max.y; y0 += kBandRows) {
                const int y1 = std::min(p.rows().max.y, y0 + kBandRows - 1);
                Imf::FrameBuffer fb;
                buffers.clear();
                for (auto c = header.channels().begin(); c != header.channels().end(); ++c) {
                    const size_t bytes = bytesOf(c.channel().type);
                    buffers.emplace_back(bytes * size_t(width) * size_t(y1 - y0 + 1));
                    char* base =
                        buffers.back().data() - (ptrdiff_t(image.min.x) + ptrdiff_t(y0) * width) * ptrdiff_t(bytes);
                    fb.insert(c.name(), Imf::Slice(c.channel().type, base, bytes, bytes * size_t(width)));
                }
                try {
                    p.file->setFrameBuffer(fb);
                    p.file->readPixels(y0, y1);
                } catch (const std::exception& e) {
                    throw std::runtime_error(p.path.string() + ": reading rows failed: " + e.what());
                }
                file.setFrameBuffer(fb);
                file.writePixels(y1 - y0 + 1);
            }
        }
    }
    out.commit();
}

}  // namespace fraktal
