// How a still is cut up: strips of full-width rows (what is held in memory and written to the
// EXR at once), each cut into square-ish tiles (what one GL draw renders). Pure, no GL.
#pragma once

#include <vector>

namespace fraktal {

struct TileRect {
    int x = 0, y = 0, width = 0, height = 0;  // pixels; y counted from the top of the image
};

// Rows [y, y + height) of the image: strips of `stripRows` rows (the last may be shorter).
std::vector<TileRect> stripsOf(int imageWidth, int imageHeight, int stripRows);
// Rows per strip of a still `imageWidth` wide rendered in tiles of `tileSize`: about 2 Mpixel
// (16 floats each, ~128 MiB) whatever the width, so memory stays bounded; at most one row of
// tiles; and a multiple of 16 rows (one EXR ZIP block) so that every strip hands OpenEXR whole
// blocks to compress in parallel.
int stillStripRows(int imageWidth, int tileSize);
// A strip cut into tiles of at most tileSize x tileSize, left to right.
std::vector<TileRect> tilesOf(const TileRect& strip, int tileSize);

}  // namespace fraktal
