#include "core/render/tiles.hpp"

#include <algorithm>

namespace fraktal {

std::vector<TileRect> stripsOf(int imageWidth, int imageHeight, int stripRows) {
    std::vector<TileRect> strips;
    for (int y = 0; y < imageHeight; y += stripRows)
        strips.push_back({0, y, imageWidth, std::min(stripRows, imageHeight - y)});
    return strips;
}

int stillStripRows(int imageWidth, int tileSize) {
    constexpr int kStripPixels = 1 << 21;
    // OpenEXR's ZIP_COMPRESSION compresses 16 scanlines at a time (ZIPS, for wide images, 1:
    // exr_writer.hpp), so a multiple of 16 rows is whole blocks either way.
    constexpr int kZipBlockRows = 16;
    const int rows =
        std::clamp(kStripPixels / std::max(1, imageWidth), kZipBlockRows, std::max(kZipBlockRows, tileSize));
    return rows / kZipBlockRows * kZipBlockRows;
}

std::vector<TileRect> tilesOf(const TileRect& strip, int tileSize) {
    std::vector<TileRect> tiles;
    for (int y = strip.y; y < strip.y + strip.height; y += tileSize)
        for (int x = strip.x; x < strip.x + strip.width; x += tileSize)
            tiles.push_back(
                {x, y, std::min(tileSize, strip.x + strip.width - x), std::min(tileSize, strip.y + strip.height - y)});
    return tiles;
}

}  // namespace fraktal
