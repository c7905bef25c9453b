#pragma once
// Tiles: the rectangles of film pixels a render hands out as units of work (to threads, to MPI
// ranks, to shards). A tile's pixels are always rendered together, by one thread, so tiles
// change nothing in the image (each pixel still sums its own samples in index order).
#include <algorithm>
#include <vector>

#include "candela/film/film_settings.h"

namespace candela {

// Film pixels [x0, x1) x [y0, y1).
struct Tile {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int pixels() const { return (x1 - x0) * (y1 - y0); }
    PixelBounds bounds() const { return {x0, y0, x1, y1}; }
    bool operator==(const Tile&) const = default;
};

// The tiles of a width x height film, `size` pixels a side (smaller at the right and bottom
// edges), row-major from the top left.
inline std::vector<Tile> make_tiles(int width, int height, int size) {
    std::vector<Tile> tiles;
    for (int y = 0; y < height; y += size)
        for (int x = 0; x < width; x += size)
            tiles.push_back({x, y, std::min(x + size, width), std::min(y + size, height)});
    return tiles;
}

}  // namespace candela
