#include "cli/encode.hpp"

#include <ImfChannelList.h>
#include <ImfFrameBuffer.h>
#include <ImfHeader.h>
#include <ImfInputFile.h>
#include <ImfStringAttribute.h>
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <numeric>

#include "cli/cancel.hpp"
#include "cli/commands.hpp"
#include "cli/process.hpp"
#include "core/anim/sequence.hpp"
#include "core/atomic_file.hpp"
#include "core/color/color_pipeline.hpp"
#include "core/image/exr_writer.hpp"
#include "core/preset.hpp"

namespace fraktal::cli {

std::vector<int> missingFrameNumbers(const std::vector<int>& sortedFrames) {
    int step = 0;
    for (size_t i = 1; i < sortedFrames.size(); ++i) step = std::gcd(step, sortedFrames[i] - sortedFrames[i - 1]);
    std::vector<int> missing;
    if (step <= 0) return missing;
    for (size_t i = 1; i < sortedFrames.size(); ++i)
        for (int f = sortedFrames[i - 1] + step; f < sortedFrames[i]; f += step) missing.push_back(f);
    return missing;
}

std::vector<std::string> ffmpegArguments(const VideoSettings& video, const std::filesystem::path& output) {
    char fps[32];
    std::snprintf(fps, sizeof fps, "%.6g", video.fps);
    std::vector<std::string> a = {video.ffmpeg,  "-hide_banner",
                                  "-loglevel",   "error",
                                  "-nostats",    "-y",
                                  "-f",          "rawvideo",
                                  "-pix_fmt",    "rgb24",
                                  "-video_size", std::to_string(video.width) + "x" + std::to_string(video.height),
                                  "-framerate",  fps,
                                  "-i",          "pipe:0",
                                  "-an"};
    // RGB to Y'CbCr with the BT.709 matrix in video range (swscale's default would be BT.601).
    const std::string toYuv709 = "scale=out_color_matrix=bt709:out_range=tv";
    switch (video.codec) {
        case VideoCodec::H264:
            // 4:2:0 needs even sides: pad odd ones by a row or column.
            a.insert(a.end(), {"-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2," + toYuv709 + ",format=yuv420p", "-c:v",
                               "libx264", "-preset", "medium", "-crf", std::to_string(video.crf), "-pix_fmt", "yuv420p",
                               "-colorspace", "bt709", "-color_range", "tv"});
            break;
        case VideoCodec::ProRes:
            a.insert(a.end(),
                     {"-vf", toYuv709 + ",format=yuv422p10le", "-c:v", "prores_ks", "-profile:v", "3", "-vendor",
                      "apl0", "-pix_fmt", "yuv422p10le", "-colorspace", "bt709", "-color_range", "tv"});
            break;
        case VideoCodec::Ffv1:
            a.insert(a.end(), {"-c:v", "ffv1", "-level", "3", "-pix_fmt", "bgr0", "-colorspace", "rgb"});
            break;
    }
    a.insert(a.end(), {"-color_primaries", "bt709"});
    if (video.srgbTransfer) a.insert(a.end(), {"-color_trc", "iec61966-2-1"});
    a.push_back(output.string());
    return a;
}

namespace {

struct EncodeOptions {
    std::string pattern;
    std::string output;
    std::string codec = "h264";
    int crf = 18;
    std::optional<double> fps;
    std::string view, display;
    std::optional<double> exposure;
    bool allowGaps = false;
    std::string ffmpeg = "ffmpeg";
    bool quiet = false;
};

// One frame's header facts, read (and checked) before ffmpeg starts.
struct FrameInfo {
    std::filesystem::path path;
    int width = 0, height = 0;
    std::string workingSpace;      // the EXR's declared colour space (fraktal.workingSpace)
    std::optional<Preset> preset;  // the embedded preset, when the frame has one
    std::optional<double> fps;     // the animation's frame rate embedded in the preset
};

FrameInfo readFrameInfo(const std::filesystem::path& path) {
    FrameInfo info;
    info.path = path;
    try {
        Imf::InputFile in(path.c_str());
        const Imath::Box2i dw = in.header().dataWindow();
        info.width = dw.max.x - dw.min.x + 1;
        info.height = dw.max.y - dw.min.y + 1;
        for (const char* c : {"R", "G", "B"})
            if (!in.header().channels().findChannel(c))
                throw std::runtime_error(std::string("no ") + c + " channel (an RGB image is needed)");
        if (const auto* part = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPartAttribute))
            throw std::runtime_error("a part " + part->value() +
                                     " of a still, not a frame (fraktal merge joins parts)");
        if (const auto* ws = in.header().findTypedAttribute<Imf::StringAttribute>(kExrWorkingSpaceAttribute))
            info.workingSpace = ws->value();
        if (const auto* p = in.header().findTypedAttribute<Imf::StringAttribute>(kExrPresetAttribute)) {
            info.preset = parsePreset(p->value(), path.string() + " (embedded preset)");
            if (auto f = info.preset->extra.find("animationFps");
                f != info.preset->extra.end() && f->is_number() && f->get<double>() > 0)
                info.fps = f->get<double>();
        }
    } catch (const PresetError&) {
        throw;
    } catch (const std::exception& e) {
        throw std::runtime_error(path.string() + ": not a readable EXR frame: " + e.what());
    }
    return info;
}

// The frame's R G B (A is not needed: the video is opaque) as packed RGBA floats, alpha 1.
void readFrameRgba(const FrameInfo& frame, std::vector<float>& rgba) {
    try {
        Imf::InputFile in(frame.path.c_str());
        const Imath::Box2i dw = in.header().dataWindow();
        rgba.assign(size_t(frame.width) * size_t(frame.height) * 4, 1.0f);
        char* base = reinterpret_cast<char*>(rgba.data()) -
                     (ptrdiff_t(dw.min.x) + ptrdiff_t(dw.min.y) * frame.width) * ptrdiff_t(4 * sizeof(float));
        Imf::FrameBuffer fb;
        const char* names[] = {"R", "G", "B"};
        for (int c = 0; c < 3; ++c)
            fb.insert(names[c], Imf::Slice(Imf::FLOAT, base + c * sizeof(float), 4 * sizeof(float),
                                           4 * sizeof(float) * size_t(frame.width)));
        in.setFrameBuffer(fb);
        in.readPixels(dw.min.y, dw.max.y);
    } catch (const std::exception& e) {
        throw std::runtime_error(frame.path.string() + ": cannot read its pixels: " + e.what());
    }
}

VideoCodec parseCodec(const std::string& name) {
    if (name == "h264") return VideoCodec::H264;
    if (name == "prores") return VideoCodec::ProRes;
    if (name == "ffv1") return VideoCodec::Ffv1;
    throw std::runtime_error("--codec '" + name + "': expected h264, prores or ffv1");
}

int runEncode(const EncodeOptions& o) {
    const VideoCodec codec = parseCodec(o.codec);
    const std::filesystem::path folder = std::filesystem::path(o.pattern).parent_path();
    std::error_code ec;
    if (!folder.empty() && !std::filesystem::is_directory(folder, ec))
        throw std::runtime_error(o.pattern + ": no frame folder " + folder.string());
    const auto onDisk = framesOnDisk(o.pattern);
    if (onDisk.empty())
        throw std::runtime_error(o.pattern + ": no frames found (files named like " + framePath(o.pattern, 0).string() +
                                 ")");
    std::vector<int> numbers;
    for (const auto& [n, path] : onDisk) numbers.push_back(n);
    if (const std::vector<int> missing = missingFrameNumbers(numbers); !missing.empty() && !o.allowGaps) {
        std::string list;
        for (size_t i = 0; i < missing.size() && i < 10; ++i) list += (i ? ", " : "") + std::to_string(missing[i]);
        if (missing.size() > 10) list += ", ...";
        throw std::runtime_error(o.pattern + ": " + std::to_string(missing.size()) + " frame(s) missing between " +
                                 std::to_string(numbers.front()) + " and " + std::to_string(numbers.back()) + " (" +
                                 list + "), e.g. " + framePath(o.pattern, missing.front()).string() +
                                 "; render them, or pass --allow-gaps");
    }

    // Every frame's header is checked before ffmpeg starts: a bad frame fails fast, no video.
    std::vector<FrameInfo> frames;
    for (const auto& [n, path] : onDisk) {
        frames.push_back(readFrameInfo(path));
        const FrameInfo& f = frames.back();
        if (f.width != frames.front().width || f.height != frames.front().height)
            throw std::runtime_error(path.string() + ": size " + std::to_string(f.width) + "x" +
                                     std::to_string(f.height) + ", but " + frames.front().path.string() + " is " +
                                     std::to_string(frames.front().width) + "x" +
                                     std::to_string(frames.front().height));
    }
    const FrameInfo& first = frames.front();
    // The preset's display, view and exposure (the still exporter's PNG preview), unless overridden.
    RenderSettings look = first.preset ? first.preset->render : RenderSettings{};
    if (!o.display.empty()) look.display = o.display;
    if (!o.view.empty()) look.view = o.view;
    if (o.exposure) look.exposure = *o.exposure;
    const ColorPipeline color = ColorPipeline::fromEnvironment();
    color.checkDisplayView(look.display, look.view);
    std::string workingSpace;
    try {
        workingSpace = color.resolveSpace(first.workingSpace.empty() ? "scene_linear" : first.workingSpace);
    } catch (const std::exception& e) {
        throw std::runtime_error(first.path.string() + ": its colour space (" + kExrWorkingSpaceAttribute +
                                 "): " + e.what());
    }
    for (const FrameInfo& f : frames)
        if (f.workingSpace != first.workingSpace)
            throw std::runtime_error(f.path.string() + ": colour space '" + f.workingSpace + "', but " +
                                     first.path.string() + " is in '" + first.workingSpace + "'");
    const DisplayTransform display(color, workingSpace, look.display, look.view, look.exposure);

    VideoSettings video;
    video.codec = codec;
    video.crf = o.crf;
    video.fps = o.fps ? *o.fps : first.fps.value_or(24.0);
    video.width = first.width;
    video.height = first.height;
    video.ffmpeg = o.ffmpeg;
    video.srgbTransfer = look.display == "sRGB" && look.view != "Raw";

    const std::atomic<bool>& cancel = cancelOnSignal();  // from before ffmpeg makes its file
    AtomicFile out(o.output);                            // checks the folder; the video goes to a temporary name first
    const std::vector<std::string> argv = ffmpegArguments(video, out.tempPath());
    if (!o.quiet)
        std::fprintf(stderr, "encoding %zu frames %dx%d at %g fps (%s, %s/%s) into %s\n", frames.size(), video.width,
                     video.height, video.fps, o.codec.c_str(), look.display.c_str(), look.view.c_str(),
                     o.output.c_str());
    std::unique_ptr<RunningProgram> ffmpeg;
    try {
        ffmpeg = std::make_unique<RunningProgram>(argv);
    } catch (const ProgramNotStarted& e) {
        throw std::runtime_error(std::string(e.what()) +
                                 "; fraktal encode needs the ffmpeg program (Debian package "
                                 "ffmpeg, or --ffmpeg PATH); no video written");
    }
    std::vector<float> rgba;
    std::vector<uint8_t> rgb8(size_t(video.width) * size_t(video.height) * 3);
    bool fed = true;
    size_t i = 0;
    for (; i < frames.size() && fed && !cancel; ++i) {
        readFrameRgba(frames[i], rgba);
        display.toDisplay8(rgba, rgb8);
        fed = ffmpeg->write(rgb8);
        if (!o.quiet && (::isatty(STDERR_FILENO) || (i + 1) % 24 == 0 || i + 1 == frames.size()))
            std::fprintf(stderr, "%sframe %zu/%zu: %s%s", ::isatty(STDERR_FILENO) ? "\r" : "", i + 1, frames.size(),
                         frames[i].path.filename().c_str(),
                         ::isatty(STDERR_FILENO) && i + 1 < frames.size() ? "   " : "\n");
    }
    if (cancel) {
        // Ctrl+C reaches ffmpeg too when both run in a terminal. ffmpeg is killed and reaped, then
        // the temporary video removed (the destructors, in that order): an existing video at the
        // destination stays as it was.
        ffmpeg.reset();
        std::fprintf(stderr, "\nfraktal: encode cancelled after %zu of %zu frames; no video written\n", i,
                     frames.size());
        return kCancelledExitCode;
    }
    const ProgramResult r = ffmpeg->wait();
    if (!fed || r.exitCode != 0 || r.signal) {
        const std::string why = tailOf(r.err);
        throw std::runtime_error(video.ffmpeg + " failed (" + r.describeStatus() + ") encoding " + o.output +
                                 (why.empty() ? std::string() : ": " + why) + "; no video written");
    }
    out.commit();
    if (!o.quiet) std::fprintf(stderr, "wrote %s\n", o.output.c_str());
    return 0;
}

}  // namespace

void addEncodeCommand(CLI::App& app, Action& action) {
    auto o = std::make_shared<EncodeOptions>();
    CLI::App* cmd =
        app.add_subcommand("encode", "Encode an EXR frame sequence into a video through the OCIO display transform");
    cmd->add_option("frames", o->pattern,
                    "The frames: a pattern whose run of # is the frame number, e.g. out/frame_####.exr")
        ->required();
    cmd->add_option("-o,--output", o->output, "Output video (.mp4, .mov, .mkv; written atomically)")->required();
    cmd->add_option("--codec", o->codec, "h264 (default; yuv420p), prores (422 HQ, for editing) or ffv1 (lossless)")
        ->check(CLI::IsMember({"h264", "prores", "ffv1"}));
    cmd->add_option("--crf", o->crf, "H.264 quality: 0 (lossless) to 51; default 18")->check(CLI::Range(0, 51));
    cmd->add_option("--fps", o->fps, "Frame rate (default: the animation's, embedded in the frames, else 24)")
        ->check(CLI::Range(0.1, 1000.0));
    cmd->add_option("--view", o->view, "OCIO view (default: the frames' preset's, e.g. Standard)");
    cmd->add_option("--display", o->display, "OCIO display (default: the frames' preset's, e.g. sRGB)");
    cmd->add_option("--exposure", o->exposure, "Exposure in stops (default: the frames' preset's)")
        ->check(CLI::Range(-20.0, 20.0));
    cmd->add_flag("--allow-gaps", o->allowGaps, "Encode the frames found even when some are missing");
    cmd->add_option("--ffmpeg", o->ffmpeg, "The ffmpeg program (default: ffmpeg on PATH)");
    cmd->add_flag("-q,--quiet", o->quiet, "No progress output");
    cmd->callback([&action, o] { action = [o] { return runEncode(*o); }; });
}

}  // namespace fraktal::cli
