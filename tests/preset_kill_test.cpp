// A process saving a preset is killed with SIGKILL at random moments, many times: the file on
// disk is always the complete old or the complete new version, never a mix, a truncation or a
// missing file; the backup is always a complete preset too.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <random>
#include <sstream>
#include <thread>

#include "test_support.hpp"

using namespace fraktal;

namespace {

std::string readAll(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

TEST(PresetSave, KilledMidSaveLeavesTheOldOrTheNewFile) {
    const auto dir = std::filesystem::temp_directory_path() / ("fraktal_kill_" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const auto file = dir / "scene.json";

    // Two versions that differ in size and content, with long descriptions so that a save takes
    // long enough to be interrupted in the middle.
    Preset a = loadPreset(test::sourceDir() / "presets/mandelbox.json");
    Preset b = a;
    a.description = std::string(60000, 'a');
    b.description = std::string(30000, 'b');
    b.formula.nodes[0].values[0].x = 1.5;
    const std::string textA = serializePreset(a), textB = serializePreset(b);
    savePresetFile(file, a);
    savePresetFile(file, a);  // so that a backup exists even if the first child dies at once

    std::mt19937 rng(99);
    std::uniform_int_distribution<int> delayMicros(0, 3000);
    int sawA = 0, sawB = 0;
    for (int round = 0; round < 60; ++round) {
        const pid_t child = fork();
        ASSERT_GE(child, 0);
        if (child == 0) {
            for (int i = 0;; ++i) {
                try {
                    savePresetFile(file, i % 2 ? a : b);
                } catch (...) {
                    _exit(3);
                }
            }
        }
        std::this_thread::sleep_for(std::chrono::microseconds(delayMicros(rng)));
        kill(child, SIGKILL);
        int status = 0;
        waitpid(child, &status, 0);
        ASSERT_TRUE(WIFSIGNALED(status)) << "the saving process stopped by itself (status " << status << ")";

        const std::string now = readAll(file);
        ASSERT_TRUE(now == textA || now == textB) << "round " << round << ": the file is neither version ("
                                                  << now.size() << " bytes)";
        (now == textA ? sawA : sawB)++;
        const std::string backup = readAll(file.string() + ".bak");
        ASSERT_TRUE(backup == textA || backup == textB) << "round " << round << ": the backup is broken";
        EXPECT_NO_THROW(loadPreset(file));
    }
    EXPECT_GT(sawA + sawB, 0);
    std::printf("killed 60 saves: %d left version A on disk, %d version B\n", sawA, sawB);
    // Temporary files of killed saves may remain (hidden, named .scene.tmp-*); never the preset.
    std::filesystem::remove_all(dir);
}

TEST(PresetSave, KeepsTheBackupOfThePreviousVersion) {
    const auto dir = std::filesystem::temp_directory_path() / ("fraktal_bak_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    const auto file = dir / "scene.json";
    Preset p = loadPreset(test::sourceDir() / "presets/menger.json");
    savePresetFile(file, p);
    EXPECT_FALSE(std::filesystem::exists(file.string() + ".bak"));
    const std::string first = readAll(file);
    p.formula.iterations = 5;
    savePresetFile(file, p);
    EXPECT_EQ(readAll(file.string() + ".bak"), first);
    EXPECT_EQ(loadPreset(file).formula.iterations, 5);
    std::filesystem::remove_all(dir);
}
