// A still that would not fit in memory is refused before anything is rendered, with the estimate
// in the message; the estimate of a 16384x16384 EXR stays within the bound it is held to.
#include <gtest/gtest.h>

#include "core/color/color_pipeline.hpp"
#include "core/render/still_job.hpp"
#include "test_support.hpp"

namespace fraktal {
namespace {

StillJob bigJob(int side, bool png) {
    StillJob job;
    job.preset = loadPreset(test::sourceDir() / "presets" / "menger.json");
    job.preset.render.width = side;
    job.preset.render.height = side;
    job.preset.render.spp = 1;
    job.exr = std::filesystem::temp_directory_path() / "fraktal_memory_test.exr";
    if (png) job.png = std::filesystem::temp_directory_path() / "fraktal_memory_test.png";
    return job;
}

TEST(StillMemory, EstimateGrowsWithThePreviewAndStaysBoundedWithout) {
    const long long exrOnly = estimateStillMemoryBytes(bigJob(16384, false));
    const long long withPng = estimateStillMemoryBytes(bigJob(16384, true));
    EXPECT_LT(exrOnly, 1500LL << 20);                   // the bound for 16384x16384 at 1 spp
    EXPECT_GE(withPng - exrOnly, 16384LL * 16384 * 3);  // the 8-bit preview holds the whole image
    EXPECT_LT(estimateStillMemoryBytes(bigJob(256, false)), exrOnly);
}

TEST(StillMemory, TooBigForTheMemoryIsRefusedWithTheEstimate) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    StillJob job = bigJob(16384, true);
    job.memoryLimitBytes = 512LL << 20;
    try {
        validateStillJob(job, color);
        FAIL() << "a job over the memory limit was accepted";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("16384x16384"), std::string::npos) << message;
        EXPECT_NE(
            message.find("estimated " + std::to_string((estimateStillMemoryBytes(job) + (1 << 20) - 1) >> 20) + " MB"),
            std::string::npos)
            << message;
        EXPECT_NE(message.find("512 MB is available"), std::string::npos) << message;
    }
    EXPECT_FALSE(std::filesystem::exists(job.exr));
    job.memoryLimitBytes = 4096LL << 20;
    job.checkDisk = false;  // this machine's free disk is not what this test is about
    EXPECT_NO_THROW(validateStillJob(job, color));
    EXPECT_GT(availableMemoryBytes(), 0);
}

// The EXR may take its uncompressed size at most; a disk with less free space than that is refused
// before anything is rendered, naming the file and both figures, and nothing is written.
TEST(StillDisk, TooLittleFreeSpaceIsRefusedWithTheEstimate) {
    const ColorPipeline color = ColorPipeline::fromFile(shippedOcioConfigPath());
    StillJob job = bigJob(32768, false);
    const long long needed = estimateStillDiskBytes(job);
    EXPECT_GE(needed, 32768LL * 32768 * 30);  // 13 channels: 11 half, 2 float
    EXPECT_LT(needed, 32768LL * 32768 * 30 + (4LL << 20));
    // A part needs its rows only; a PNG preview adds its raw rows.
    job.partCount = 4;
    EXPECT_LT(estimateStillDiskBytes(job), needed / 4 + (4LL << 20));
    job.partCount = 1;
    StillJob withPng = bigJob(16384, true);
    EXPECT_GT(estimateStillDiskBytes(withPng) - estimateStillDiskBytes(bigJob(16384, false)), 16384LL * 16384 * 3);

    job.diskLimitBytes = 20LL * 1000 * 1000 * 1000;
    try {
        validateStillJob(job, color);
        FAIL() << "a job over the free disk space was accepted";
    } catch (const std::runtime_error& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find(job.exr.string() + ": the output may take up to 32.2 GB"), std::string::npos) << message;
        EXPECT_NE(message.find("has 20.0 GB free"), std::string::npos) << message;
        EXPECT_NE(message.find("--no-disk-check"), std::string::npos) << message;
    }
    EXPECT_FALSE(std::filesystem::exists(job.exr));
    job.diskLimitBytes = needed;
    EXPECT_NO_THROW(validateStillJob(job, color));
    job.diskLimitBytes = needed - 1;
    EXPECT_THROW(validateStillJob(job, color), std::runtime_error);
    job.checkDisk = false;
    EXPECT_NO_THROW(validateStillJob(job, color));
}

}  // namespace
}  // namespace fraktal
