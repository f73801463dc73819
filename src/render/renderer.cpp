#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <vector>

#include "render/tile_renderer.h"
#include "util/parallel_for.h"

namespace whitted {
namespace {

std::vector<Tile> cut_into_tiles(const PixelRegion& r, int tile_size) {
    const int ts = std::max(1, tile_size);
    std::vector<Tile> tiles;
    for (int y = r.y0; y < r.y1; y += ts)
        for (int x = r.x0; x < r.x1; x += ts) tiles.push_back({x, y, std::min(x + ts, r.x1), std::min(y + ts, r.y1)});
    return tiles;
}

}  // namespace

int RenderJob::tile_count() const { return int(cut_into_tiles(render_region(), tile_size).size()); }

RenderStats render(const Integrator& integrator, const RenderJob& job, Film& film) {
    return render_tiles(integrator, job, cut_into_tiles(job.render_region(), job.tile_size), film);
}

RenderStats render_tiles(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                         Film& film) {
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    stats.tiles_total = int(tiles.size());
    stats.threads = worker_count(job.threads, tiles.size());

    // One renderer (scratch buffers, ray counts) per worker, each on cache lines of its own.
    std::vector<TileRenderer> workers;
    workers.reserve(std::size_t(stats.threads));
    for (int w = 0; w < stats.threads; ++w) workers.emplace_back(integrator, job);
    alignas(64) std::atomic<int> done{0};
    parallel_for(tiles.size(), stats.threads, [&](std::size_t i, int w) {
        if (job.cancel && job.cancel->load(std::memory_order_relaxed)) return;
        if (!workers[std::size_t(w)].render(tiles[i], film)) return;
        done.fetch_add(1, std::memory_order_relaxed);
        if (job.on_tile) job.on_tile(tiles[i]);
    });
    for (const TileRenderer& w : workers) stats.rays += w.counts();

    stats.tiles_done = done.load();
    stats.cancelled = stats.tiles_done < stats.tiles_total;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

RenderStats render(const Scene& scene, const RenderJob& job, Image& image) {
    const auto integrator = make_integrator(scene, job.camera_for(scene), job.integrator);
    Film film(job.width, job.height);
    RenderStats stats = render(*integrator, job, film);
    film.write_to(image, job.render_region());
    return stats;
}

}  // namespace whitted
