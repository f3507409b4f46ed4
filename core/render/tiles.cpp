#include "core/render/tiles.hpp"

#include <algorithm>

namespace fraktal {

std::vector<TileRect> stripsOf(int imageWidth, int imageHeight, int stripRows) {
    std::vector<TileRect> strips;
    for (int y = 0; y < imageHeight; y += stripRows)
        strips.push_back({0, y, imageWidth, std::min(stripRows, imageHeight - y)});
    return strips;
}

std::vector<TileRect> tilesOf(const TileRect& strip, int tileSize) {
    std::vector<TileRect> tiles;
    for (int y = strip.y; y < strip.y + strip.height; y += tileSize)
        for (int x = strip.x; x < strip.x + strip.width; x += tileSize)
            tiles.push_back({x, y, std::min(tileSize, strip.x + strip.width - x), std::min(tileSize, strip.y + strip.height - y)});
    return tiles;
}

}  // namespace fraktal
