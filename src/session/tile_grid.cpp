#include "session/tile_grid.h"

#include <cstring>

namespace whitted {

void append_tile_pixels(const Film& film, const Tile& t, std::vector<char>& out) {
    for (int y = t.y0; y < t.y1; ++y) {
        const char* row = reinterpret_cast<const char*>(&film.at(t.x0, y));
        out.insert(out.end(), row, row + std::size_t(t.width()) * sizeof(FilmPixel));
    }
}

bool read_tile_pixels(const char*& in, const char* end, const Tile& t, Film& film) {
    const std::size_t row_bytes = std::size_t(t.width()) * sizeof(FilmPixel);
    if (std::size_t(end - in) < row_bytes * std::size_t(t.height())) return false;
    for (int y = t.y0; y < t.y1; ++y, in += row_bytes) std::memcpy(&film.at(t.x0, y), in, row_bytes);
    return true;
}

}  // namespace whitted
