// Pure parts of the still path: the reconstruction filter and the tiling.
#include <gtest/gtest.h>

#include <cmath>

#include "core/render/filter.hpp"
#include "core/render/tiles.hpp"

namespace fraktal {
namespace {

TEST(BlackmanHarris, WindowShape) {
    EXPECT_NEAR(blackmanHarris(0.0), 1.0, 1e-12);
    EXPECT_NEAR(blackmanHarris(1.0), 0.0, 1e-12);
    EXPECT_NEAR(blackmanHarris(0.999999), 0.0, 1e-4);
    EXPECT_NEAR(blackmanHarris(0.3), blackmanHarris(-0.3), 1e-12);
    EXPECT_GT(blackmanHarris(0.2), blackmanHarris(0.5));
}

TEST(BlackmanHarris, CdfIsTheIntegralOfTheWindow) {
    double integral = 0.0, total = 0.0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) total += blackmanHarris(-1.0 + (i + 0.5) * 2.0 / n) * 2.0 / n;
    for (int i = 0; i < n; ++i) {
        const double x = -1.0 + (i + 0.5) * 2.0 / n;
        if (x < 0.25) integral += blackmanHarris(x) * 2.0 / n;
    }
    EXPECT_NEAR(blackmanHarrisCdf(0.25), integral / total, 1e-3);
    EXPECT_NEAR(blackmanHarrisCdf(0.0), 0.5, 1e-12);
}

TEST(BlackmanHarris, InverseTableInvertsTheCdf) {
    const std::vector<float> table = blackmanHarrisInverseCdfTable(65);
    ASSERT_EQ(table.size(), 65u);
    EXPECT_NEAR(table.front(), -1.0f, 1e-5);
    EXPECT_NEAR(table.back(), 1.0f, 1e-5);
    EXPECT_NEAR(table[32], 0.0f, 1e-6);
    for (size_t i = 1; i < table.size(); ++i) {
        EXPECT_GT(table[i], table[i - 1]);
        EXPECT_NEAR(blackmanHarrisCdf(table[i]), double(i) / 64.0, 1e-5);
    }
}

TEST(Tiles, CoverEveryPixelOnce) {
    const int w = 1000, h = 333;
    std::vector<int> hits(size_t(w) * h, 0);
    for (const TileRect& strip : stripsOf(w, h, 64)) {
        EXPECT_EQ(strip.width, w);
        for (const TileRect& t : tilesOf(strip, 128)) {
            EXPECT_LE(t.width, 128);
            EXPECT_LE(t.height, 64);
            for (int y = t.y; y < t.y + t.height; ++y)
                for (int x = t.x; x < t.x + t.width; ++x) ++hits[size_t(y) * w + x];
        }
    }
    for (int v : hits) ASSERT_EQ(v, 1);
}

// Strips stay near 2 Mpixel at any width (bounded memory), hold whole EXR ZIP blocks (16 rows)
// and never more than one row of tiles.
TEST(Tiles, StillStripRowsAreBoundedWholeZipBlocks) {
    for (int width : {1, 100, 1000, 1920, 4096, 8192, 16384, 65536})
        for (int tile : {16, 64, 100, 256, 4096}) {
            const int rows = stillStripRows(width, tile);
            EXPECT_EQ(rows % 16, 0) << width << " " << tile;
            EXPECT_GE(rows, 16);
            EXPECT_LE(rows, std::max(16, tile));
            EXPECT_LE(double(rows) * width, std::max(16.0 * width, double(1 << 21))) << width << " " << tile;
        }
    EXPECT_EQ(stillStripRows(8192, 256), 256);
    EXPECT_EQ(stillStripRows(16384, 256), 128);
}

}  // namespace
}  // namespace fraktal
