#include "core/anim/sequence.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>

#include <algorithm>
#include <regex>
#include <stdexcept>

#include "core/image/exr_writer.hpp"
#include "core/render/still_job.hpp"

namespace fraktal {

std::vector<int> FrameRange::frames() const {
    std::vector<int> out;
    for (int f = first; f <= last; f += step) out.push_back(f);
    return out;
}

FrameRange parseFrameRange(const std::string& text) {
    std::smatch m;
    if (!std::regex_match(text, m, std::regex(R"((\d{1,8})(?:-(\d{1,8}))?(?::(\d{1,8}))?)")))
        throw std::runtime_error("--frames '" + text + "': expected FIRST-LAST[:STEP], e.g. 0-239 or 0-239:2");
    FrameRange r;
    r.first = std::stoi(m[1]);
    r.last = m[2].matched ? std::stoi(m[2]) : r.first;
    r.step = m[3].matched ? std::stoi(m[3]) : 1;
    if (r.last < r.first) throw std::runtime_error("--frames '" + text + "': the last frame is before the first");
    if (r.step < 1) throw std::runtime_error("--frames '" + text + "': the step must be at least 1");
    return r;
}

void checkFrameRangeWithin(const FrameRange& range, const Animation& animation, const std::string& presetName) {
    if (animation.empty())
        throw std::runtime_error(presetName + ": has no animation section (keyframes); --frames renders animations");
    if (range.first < animation.firstFrame || range.last > animation.lastFrame)
        throw std::runtime_error("--frames " + std::to_string(range.first) + "-" + std::to_string(range.last) +
                                 " is outside the animation of " + presetName + " (frames " +
                                 std::to_string(animation.firstFrame) + "-" + std::to_string(animation.lastFrame) +
                                 ", animation.firstFrame / animation.lastFrame)");
}

namespace {

// Position and length of the pattern's one run of '#'.
std::pair<size_t, size_t> hashRun(const std::string& pattern) {
    const std::string name = std::filesystem::path(pattern).filename().string();
    const size_t begin = pattern.size() - name.size() + name.find('#');
    if (name.find('#') == std::string::npos)
        throw std::runtime_error(pattern +
                                 ": a frame sequence needs '#' in the file name for the frame number, "
                                 "e.g. out/frame_####.exr");
    size_t end = begin;
    while (end < pattern.size() && pattern[end] == '#') ++end;
    if (pattern.find('#', end) != std::string::npos)
        throw std::runtime_error(pattern + ": more than one run of '#' in the file name");
    return {begin, end - begin};
}

}  // namespace

void checkFramePattern(const std::string& pattern) {
    hashRun(pattern);
    const std::filesystem::path folder = std::filesystem::path(pattern).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        throw std::runtime_error(pattern + ": the output folder " + folder.string() +
                                 " does not exist (create it first)");
}

std::filesystem::path framePath(const std::string& pattern, int frame) {
    const auto [begin, width] = hashRun(pattern);
    std::string number = std::to_string(frame);
    if (number.size() < width) number.insert(0, width - number.size(), '0');
    return pattern.substr(0, begin) + number + pattern.substr(begin + width);
}

std::vector<std::pair<int, std::filesystem::path>> framesOnDisk(const std::string& pattern) {
    checkFramePattern(pattern);
    const auto [begin, width] = hashRun(pattern);
    const std::filesystem::path folder = std::filesystem::path(pattern).parent_path();
    const std::string name = std::filesystem::path(pattern).filename().string();
    const size_t nameBegin = begin - (pattern.size() - name.size());
    const std::string prefix = name.substr(0, nameBegin), suffix = name.substr(nameBegin + width);
    std::vector<std::pair<int, std::filesystem::path>> out;
    for (const auto& entry : std::filesystem::directory_iterator(folder.empty() ? "." : folder)) {
        const std::string file = entry.path().filename().string();
        if (file.size() < prefix.size() + width + suffix.size() || !file.starts_with(prefix) || !file.ends_with(suffix))
            continue;
        const std::string digits = file.substr(prefix.size(), file.size() - prefix.size() - suffix.size());
        if (digits.size() > 9 ||
            !std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; }))
            continue;
        out.emplace_back(std::stoi(digits), folder.empty() ? std::filesystem::path(file) : folder / file);
    }
    std::sort(out.begin(), out.end());
    return out;
}

Preset sequenceFramePreset(const Preset& animated, int frame) {
    Preset p = presetAtFrame(animated, frame);
    p.extra["animationFrame"] = frame;
    // The frame rate travels with every frame, for `fraktal encode`.
    p.extra["animationFps"] = animated.animation.fps;
    return p;
}

FrameFileState checkFrameFile(const std::filesystem::path& path, const Preset& preset, std::string* why, int partIndex,
                              int partCount) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return FrameFileState::Missing;
    auto broken = [&](const std::string& reason) {
        if (why) *why = reason;
        return FrameFileState::Broken;
    };
    try {
        Imf::InputFile in(path.c_str());
        const Imath::Box2i dw = in.header().dataWindow();
        const int width = dw.max.x - dw.min.x + 1;
        const auto [firstRow, endRow] = partRows(preset.render.height, partIndex, partCount);
        if (width != preset.render.width || dw.min.y != firstRow || dw.max.y != endRow - 1)
            return broken("rows " + std::to_string(dw.min.y) + "-" + std::to_string(dw.max.y) + " of width " +
                          std::to_string(width) + ", expected rows " + std::to_string(firstRow) + "-" +
                          std::to_string(endRow - 1) + " of width " + std::to_string(preset.render.width));
        const auto* part = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPartAttribute);
        const std::string expectedPart =
            partCount > 1 ? std::to_string(partIndex + 1) + "/" + std::to_string(partCount) : "";
        if ((part ? part->value() : "") != expectedPart)
            return broken(part ? "it is part " + part->value() + (partCount > 1 ? ", expected " + expectedPart : "")
                               : "it is a whole image, expected part " + expectedPart);
        const auto* embedded = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPresetAttribute);
        if (!embedded) return broken("no embedded preset");
        if (embedded->value() != serializePreset(preset))
            return broken("its embedded preset is of another frame or scene");
        // Read every row of every channel (into one scratch band, channel over channel): a
        // truncated file fails here.
        constexpr int kBandRows = 64;
        std::vector<float> band(size_t(width) * kBandRows);
        for (int y0 = dw.min.y; y0 <= dw.max.y; y0 += kBandRows) {
            const int y1 = std::min(dw.max.y, y0 + kBandRows - 1);
            char* base = reinterpret_cast<char*>(band.data()) -
                         (ptrdiff_t(dw.min.x) + ptrdiff_t(y0) * width) * ptrdiff_t(sizeof(float));
            Imf::FrameBuffer fb;
            for (auto c = in.header().channels().begin(); c != in.header().channels().end(); ++c)
                fb.insert(c.name(), Imf::Slice(Imf::FLOAT, base, sizeof(float), sizeof(float) * size_t(width)));
            in.setFrameBuffer(fb);
            in.readPixels(y0, y1);
        }
    } catch (const std::exception& e) {
        return broken(std::string("unreadable: ") + e.what());
    }
    return FrameFileState::Complete;
}

}  // namespace fraktal
