// Image sequences: frame ranges ("0-239", "0-239:2", "12"), numbered output paths
// ("out/frame_####.exr") and the check that decides whether a frame already on disk is complete.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/preset.hpp"

namespace fraktal {

struct FrameRange {
    int first = 0;
    int last = 0;
    int step = 1;
    std::vector<int> frames() const;
};

// "A-B[:STEP]" or "A"; throws std::runtime_error naming the text and what is wrong.
FrameRange parseFrameRange(const std::string& text);
// Throws when `range` reaches outside the animation's frames (naming both).
void checkFrameRangeWithin(const FrameRange& range, const Animation& animation, const std::string& presetName);

// A pattern's run of '#' replaced by the zero-padded frame number (wider numbers are not cut).
// Throws when the pattern has no run of '#', or more than one, or its folder does not exist.
void checkFramePattern(const std::string& pattern);
std::filesystem::path framePath(const std::string& pattern, int frame);
// The files of the pattern's folder that the pattern names (the run of '#' matched by at least as
// many digits), by frame number, in increasing order.
std::vector<std::pair<int, std::filesystem::path>> framesOnDisk(const std::string& pattern);

// The preset rendered for `frame` of `animated`: its tracks applied, and the frame number kept in
// the preset (so the EXR says which frame it is, and a stale file of another frame is not taken).
Preset sequenceFramePreset(const Preset& animated, int frame);

// Whether `path` holds the complete EXR of `preset` (readable to its last row, of the preset's
// size, embedding exactly this preset). `why` says what is wrong when it is not. With partCount > 1,
// the file must be part partIndex (from 0) of partCount of the still (`fraktal render --tile i/n`).
enum class FrameFileState { Missing, Complete, Broken };
FrameFileState checkFrameFile(const std::filesystem::path& path, const Preset& preset, std::string* why = nullptr,
                              int partIndex = 0, int partCount = 1);

}  // namespace fraktal
