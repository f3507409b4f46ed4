// `fraktal encode out/frame_####.exr -o anim.mp4`: an EXR frame sequence through the OCIO display
// transform of the still exporter's PNG preview, piped as 8-bit RGB into Debian's `ffmpeg` program.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace fraktal::cli {

enum class VideoCodec { H264, ProRes, Ffv1 };

struct VideoSettings {
    VideoCodec codec = VideoCodec::H264;
    int crf = 18;  // H.264 quality (0 lossless .. 51); 18 is visually lossless
    double fps = 24.0;
    int width = 0, height = 0;
    std::string ffmpeg = "ffmpeg";
    bool srgbTransfer = true;
};

// The frame numbers missing from a sorted list: the list's step is the greatest common divisor of
// its differences (so 0,2,4 is whole and 0,2,6 misses 4).
std::vector<int> missingFrameNumbers(const std::vector<int>& sortedFrames);

// ffmpeg's arguments: raw rgb24 frames of width x height on standard input, encoded into `output`
// (the container follows its extension). H.264: yuv420p with BT.709 coefficients in video range,
// padded to even sides; ProRes 422 HQ (10-bit 4:2:2); FFV1: lossless RGB. Every stream is tagged
// BT.709 primaries (the shipped displays'), and the sRGB transfer function for an sRGB display.
std::vector<std::string> ffmpegArguments(const VideoSettings& video, const std::filesystem::path& output);

}  // namespace fraktal::cli
