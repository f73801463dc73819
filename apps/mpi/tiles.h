#pragma once
// The image cut into numbered tiles (scan order), the unit every rank renders, sends and
// checkpoints; and the rendering of a share of them on all of a rank's cores.
#include <atomic>
#include <cstdint>
#include <cstring>
#include <string_view>
#include <type_traits>
#include <vector>

#include "film/film.h"
#include "render/render_job.h"
#include "render/renderer.h"

namespace whitted::mpi {

// Pixels travel and are checkpointed as the film holds them (float sums and weights), so that
// merged films give the bytes one process would have written.
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

// 64-bit FNV-1a: the start check's and the checkpoint's fingerprint (not a defence against
// malice, a guard against mistakes).
inline std::uint64_t fnv1a(std::string_view bytes, std::uint64_t h = 14695981039346656037ull) {
    for (unsigned char c : bytes) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

// The tiles of one share, rendered: those finished (all of them unless cancelled) and their pixels.
struct RenderedShare {
    std::vector<int> tiles;  // finished, in the order they finished
    Film film;               // covers every tile of the share
    std::uint64_t rays = 0;
    double seconds = 0;
};

// Test-only knobs (hidden options): a slowed rank (-1: every rank), the other ranks slowed less (so
// that the slowed rank, even if it starts late, still gets tiles), a rank whose pixels are off by a little.
struct TestKnobs {
    int slow_rank = -1, slow_ms = 0, others_ms = 0;
    int delay_ms(int rank) const { return slow_rank < 0 || slow_rank == rank ? slow_ms : others_ms; }
    int corrupt_rank = -1;
};

// Renders `tiles` of `grid` with the job's threads; stops early when `cancel` is set.
RenderedShare render_share(const Integrator& integrator, const RenderJob& job, const TileGrid& grid,
                           const std::vector<int>& tiles, int rank, const TestKnobs& knobs);

// The pixels of tile t of `film` as bytes, and back.
void append_tile_pixels(const Film& film, const Tile& t, std::vector<char>& out);
// Reads tile t's pixels from `in` (advancing it) into `film`; false if `in` is too short.
bool read_tile_pixels(const char*& in, const char* end, const Tile& t, Film& film);
// True when tile t holds the same bytes in both films.
bool same_pixels(const Film& a, const Film& b, const Tile& t);

}  // namespace whitted::mpi
