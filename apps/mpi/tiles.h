#pragma once
// The rendering of a share of the image's tiles (session/tile_grid.h) on all of a rank's cores.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "film/film.h"
#include "render/render_job.h"
#include "render/renderer.h"
#include "session/tile_grid.h"

namespace whitted::mpi {

// Tiles handed to a rank for one pass of the session (session/session.h): their samples
// [sample_begin, sample_end), the pixels they continue from (the last whole pass; none in the first
// pass) and, with adaptive sampling, which pixels still take samples.
struct Share {
    int pass = 0;
    int sample_begin = 0, sample_end = 0;
    std::vector<int> tiles;
    Film before;                       // covers the tiles (empty in the first pass)
    std::vector<std::uint8_t> active;  // the whole image's pixels, 1 = sampling (empty: every pixel)
};

// The tiles of one share, rendered: those finished (all of them unless cancelled) and their pixels.
struct RenderedShare {
    int pass = 0;
    std::vector<int> tiles;  // finished, in the order they finished
    Film film;               // covers every tile of the share
    std::uint64_t rays = 0;
    RayCounts counts;  // by kind, with --stats' timed traversals
    double seconds = 0;
};

// Test-only knobs (hidden options): a slowed rank (-1: every rank), the other ranks slowed less (so
// that the slowed rank, even if it starts late, still gets tiles), a rank whose pixels are off by a little.
struct TestKnobs {
    int slow_rank = -1, slow_ms = 0, others_ms = 0;
    int delay_ms(int rank) const { return slow_rank < 0 || slow_rank == rank ? slow_ms : others_ms; }
    int corrupt_rank = -1;
};

// Renders `tiles` (some of the share's) of `grid` with the job's threads and the share's samples;
// stops early when job.cancel is set.
RenderedShare render_share(const Integrator& integrator, const RenderJob& job, const TileGrid& grid,
                           const Share& share, const std::vector<int>& tiles, int rank, const TestKnobs& knobs);

// The smallest region holding every tile of `tiles` (not empty).
PixelRegion box_of(const TileGrid& grid, const std::vector<int>& tiles);

// True when tile t holds the same bytes in both films.
bool same_pixels(const Film& a, const Film& b, const Tile& t);

}  // namespace whitted::mpi
