#pragma once
// The image cut into numbered tiles of one size (scan order): the unit a checkpoint stores and
// whitted-mpi's ranks render and send. The same tiles as render/renderer.h's cut_into_tiles gives
// for the whole image.
#include <algorithm>
#include <cstdint>
#include <string_view>
#include <type_traits>
#include <vector>

#include "film/film.h"
#include "render/render_job.h"

namespace whitted {

// Pixels travel and are checkpointed as the film holds them (float sums and weights), so that
// merged or resumed films give the bytes one uninterrupted process would have written.
static_assert(std::is_trivially_copyable_v<FilmPixel> && sizeof(FilmPixel) == 16);

struct TileGrid {
    int width = 0, height = 0, size = 32;
    int columns() const { return (width + size - 1) / size; }
    int rows() const { return (height + size - 1) / size; }
    int count() const { return columns() * rows(); }
    Tile tile(int i) const {
        const int x0 = (i % columns()) * size, y0 = (i / columns()) * size;
        return {x0, y0, std::min(x0 + size, width), std::min(y0 + size, height)};
    }
    int index_of(const Tile& t) const { return (t.y0 / size) * columns() + t.x0 / size; }
    int pixels(int i) const { return tile(i).width() * tile(i).height(); }
};

// 64-bit FNV-1a: the checkpoint's and whitted-mpi's start check's fingerprint (not a defence
// against malice, a guard against mistakes). Pass the result of one call as `h` of the next to
// hash bytes given in pieces.
inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 14695981039346656037ull) {
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// The pixels of tile t of `film` as bytes, and back.
void append_tile_pixels(const Film& film, const Tile& t, std::vector<char>& out);
// Reads tile t's pixels from `in` (advancing it) into `film`; false if `in` is too short.
bool read_tile_pixels(const char*& in, const char* end, const Tile& t, Film& film);

}  // namespace whitted
