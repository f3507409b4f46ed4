// `fraktal farm submit|status`: an animation (or a big still) rendered on a Slurm cluster as a job
// array. fraktal only writes the job script and submits it with sbatch; queueing, retries and node
// choice are Slurm's. Every array task runs `fraktal render --frames` on its chunk of frames (which
// skips frames already complete), or `fraktal render --tile i/n` for one part of a still, followed
// by a `fraktal merge` job that depends on the array (afterok).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "core/anim/sequence.hpp"

namespace fraktal::cli {

struct SlurmOptions {
    std::string partition, account, time;
    int cpusPerTask = 1;
    std::vector<std::string> extra;  // further sbatch options, passed as given
};

// What was asked of the farm; recorded in DIR/.farm/jobs.json so that `farm status DIR` and a
// resubmission check the same frames.
struct FarmPlan {
    std::string preset;   // absolute path of the preset (an animation, or a still with tiles)
    std::string output;   // absolute: a frame pattern (out/frame_####.exr), or the still's EXR
    std::string frames;   // FIRST-LAST[:STEP]; empty for a still in tiles
    int chunk = 8;        // frames per array task
    int tiles = 0;        // a still: the number of parts (array tasks)
    std::string size;     // --size override (empty: the preset's)
    int spp = 0;          // --spp override (0: the preset's)
    std::string fraktal;  // the fraktal program the nodes run (absolute)
    SlurmOptions slurm;
    bool isStill() const { return tiles > 0; }
};

// The frames of array task `index`: chunk `index` of the range's frames.
std::vector<int> chunkFrames(const FrameRange& range, int chunk, int index);
int chunkCount(const FrameRange& range, int chunk);
// Slurm's array index syntax for sorted indices, runs joined: {0,1,2,5,7,8} -> "0-2,5,7-8".
std::string arrayIndexList(const std::vector<int>& sortedIndices);
// A word for a POSIX shell: single-quoted unless it is plainly safe.
std::string shellQuote(const std::string& word);

// The folder of the farm's records: <the output's folder>/.farm
std::filesystem::path farmDirOf(const FarmPlan& plan);
// Part i (from 1) of a still in tiles, in the farm folder.
std::filesystem::path tilePartPath(const FarmPlan& plan, int part);

// The bash scripts sbatch runs: one array task per chunk of frames (or per tile), and the merge.
std::string frameArrayScript(const FarmPlan& plan);
std::string tileArrayScript(const FarmPlan& plan);
std::string mergeScript(const FarmPlan& plan);

}  // namespace fraktal::cli
