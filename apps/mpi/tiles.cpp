#include "tiles.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <mutex>
#include <thread>

namespace whitted::mpi {

RenderedShare render_share(const Integrator& integrator, const RenderJob& job, const TileGrid& grid,
                           const Share& share, const std::vector<int>& tiles, int rank, const TestKnobs& knobs) {
    RenderedShare out;
    out.pass = share.pass;
    if (tiles.empty()) return out;
    std::vector<Tile> rects;
    for (int t : tiles) rects.push_back(grid.tile(t));
    out.film = Film(grid.width, grid.height, box_of(grid, tiles));
    // Each tile goes on from the samples it had (the session adds a pass's samples in order).
    if (share.sample_begin > 0)
        for (const Tile& r : rects) out.film.copy_from(share.before, r);
    RenderJob j = job;
    j.tile_size = grid.size;
    j.sample_begin = share.sample_begin;
    j.sample_end = share.sample_end;
    j.active = share.active.empty() ? nullptr : &share.active;
    std::mutex m;
    j.on_tile = [&](const Tile& r) {
        if (const int ms = knobs.delay_ms(rank); ms > 0) std::this_thread::sleep_for(std::chrono::milliseconds(ms));
        std::lock_guard lock(m);
        out.tiles.push_back(grid.index_of(r));
    };
    const RenderStats stats = render_tiles(integrator, j, rects, out.film);
    out.rays = stats.rays.total();
    out.counts = stats.rays;
    out.seconds = stats.seconds;
    if (rank == knobs.corrupt_rank)
        for (int t : out.tiles) out.film.at(grid.tile(t).x0, grid.tile(t).y0).sum.x += 1e-3f;
    return out;
}

PixelRegion box_of(const TileGrid& grid, const std::vector<int>& tiles) {
    PixelRegion box = grid.tile(tiles[0]);
    for (int t : tiles) {
        const Tile r = grid.tile(t);
        box = {std::min(box.x0, r.x0), std::min(box.y0, r.y0), std::max(box.x1, r.x1), std::max(box.y1, r.y1)};
    }
    return box;
}

bool same_pixels(const Film& a, const Film& b, const Tile& t) {
    for (int y = t.y0; y < t.y1; ++y)
        if (std::memcmp(&a.at(t.x0, y), &b.at(t.x0, y), std::size_t(t.width()) * sizeof(FilmPixel)) != 0) return false;
    return true;
}

}  // namespace whitted::mpi
