// `fraktal farm`'s plans without a cluster: the job scripts it writes are run by bash with the
// array index Slurm would give and a stand-in for fraktal that prints its arguments, and what
// each task would render must be exactly its chunk of frames (or its part of the still), every
// frame once; shell quoting gives back any word unchanged. The whole path through a real Slurm is
// tests/farm_slurm_test.sh.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/farm.hpp"

using namespace fraktal;
using namespace fraktal::cli;

namespace {

std::string runBash(const std::string& script, const std::string& environment) {
    const auto path =
        std::filesystem::temp_directory_path() / ("fraktal_farm_plan_" + std::to_string(::getpid()) + ".sh");
    std::ofstream(path) << script;
    FILE* pipe = ::popen((environment + " bash " + path.string() + " 2>&1").c_str(), "r");
    std::string out;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.append(buf, n);
    ::pclose(pipe);
    std::filesystem::remove(path);
    return out;
}

// The words of one line, split on spaces (the stand-in prints its arguments joined by spaces).
std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string w; in >> w;) out.push_back(w);
    return out;
}

std::string valueAfter(const std::vector<std::string>& argv, const std::string& option) {
    for (size_t i = 0; i + 1 < argv.size(); ++i)
        if (argv[i] == option) return argv[i + 1];
    return "";
}

FarmPlan framePlan(const std::string& frames, int chunk) {
    FarmPlan plan;
    plan.preset = "/scenes/anim.json";
    plan.output = "/renders/out/frame_####.exr";
    plan.frames = frames;
    plan.chunk = chunk;
    plan.fraktal = "/bin/echo";  // prints what fraktal would be asked to do
    return plan;
}

}  // namespace

TEST(FarmPlan, EveryArrayTaskRendersItsChunkAndEveryFrameOnce) {
    struct Case {
        const char* frames;
        int chunk;
    };
    for (const Case& c :
         {Case{"0-239", 8}, Case{"0-239:100", 1}, Case{"5-17:3", 2}, Case{"10-10", 4}, Case{"0-100:7", 5}}) {
        const FarmPlan plan = framePlan(c.frames, c.chunk);
        const FrameRange range = parseFrameRange(c.frames);
        const std::string script = frameArrayScript(plan);
        const int tasks = chunkCount(range, c.chunk);
        std::vector<int> rendered;
        for (int task = 0; task < tasks; ++task) {
            const std::vector<std::string> argv =
                words(runBash(script, "SLURM_ARRAY_TASK_ID=" + std::to_string(task) + " SLURM_CPUS_PER_TASK=2"));
            ASSERT_GE(argv.size(), 2u) << c.frames << " task " << task;
            EXPECT_EQ(argv[0], "render");
            EXPECT_EQ(argv[1], plan.preset);
            EXPECT_EQ(valueAfter(argv, "-o"), plan.output);
            EXPECT_EQ(valueAfter(argv, "--threads"), "2");
            const FrameRange taskRange = parseFrameRange(valueAfter(argv, "--frames"));
            const std::vector<int> frames = taskRange.frames();
            EXPECT_EQ(frames, chunkFrames(range, c.chunk, task))
                << c.frames << " chunk " << c.chunk << " task " << task;
            rendered.insert(rendered.end(), frames.begin(), frames.end());
        }
        EXPECT_EQ(rendered, range.frames()) << c.frames << ": every frame once, in order";
        EXPECT_TRUE(chunkFrames(range, c.chunk, tasks).empty()) << "no task past the last chunk";
    }
}

TEST(FarmPlan, ArrayIndicesAreJoinedIntoRuns) {
    EXPECT_EQ(arrayIndexList({0, 1, 2, 5, 7, 8}), "0-2,5,7-8");
    EXPECT_EQ(arrayIndexList({3}), "3");
    EXPECT_EQ(arrayIndexList({}), "");
    EXPECT_EQ(arrayIndexList({0, 2, 4}), "0,2,4");
}

TEST(FarmPlan, ShellQuotingGivesEveryWordBack) {
    for (const std::string word : {"plain/path.exr", "with space", "it's", "$HOME", "a;b && c", "`x`", "\"q\"",
                                   "back\\slash", "frame_####.exr", "*", "", "new\nline", "-o"}) {
        const std::string out = runBash("printf '%s' " + shellQuote(word) + "\n", "");
        EXPECT_EQ(out, word) << "quoted as " << shellQuote(word);
    }
}

TEST(FarmPlan, TileTasksWriteThePartsTheMergeReads) {
    FarmPlan plan;
    plan.preset = "/scenes/still with space.json";
    plan.output = "/renders/big still.exr";
    plan.tiles = 5;
    plan.size = "16384x16384";
    plan.fraktal = "/bin/echo";
    const std::string tiles = tileArrayScript(plan);
    std::set<std::string> parts;
    for (int task = 0; task < plan.tiles; ++task) {
        // Paths with spaces: the stand-in's output is split on spaces, so compare whole lines.
        const std::string line = runBash(tiles, "SLURM_ARRAY_TASK_ID=" + std::to_string(task));
        const std::string expected = "render " + plan.preset + " --tile " + std::to_string(task + 1) + "/5 -o " +
                                     tilePartPath(plan, task + 1).string() + " --threads 1 --size 16384x16384\n";
        EXPECT_EQ(line, expected);
        parts.insert(tilePartPath(plan, task + 1).string());
    }
    EXPECT_EQ(parts.size(), 5u);
    std::string mergeExpected = "merge";
    for (int part = 1; part <= plan.tiles; ++part) mergeExpected += " " + tilePartPath(plan, part).string();
    EXPECT_EQ(runBash(mergeScript(plan), ""), mergeExpected + " -o " + plan.output + "\n");
}
