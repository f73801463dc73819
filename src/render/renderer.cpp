#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <vector>

#include "render/tile_renderer.h"
#include "accel/scene.h"
#include "base/parallel_for.h"

namespace whitted {

std::vector<Tile> cut_into_tiles(const PixelRegion& r, int tile_size) {
    const int ts = std::max(1, tile_size);
    std::vector<Tile> tiles;
    for (int y = r.y0; y < r.y1; y += ts)
        for (int x = r.x0; x < r.x1; x += ts) tiles.push_back({x, y, std::min(x + ts, r.x1), std::min(y + ts, r.y1)});
    return tiles;
}

Camera RenderJob::camera_for(const Scene& scene) const { return camera.value_or(scene.data.camera); }

int RenderJob::tile_count() const { return int(cut_into_tiles(render_region(), tile_size).size()); }

bool same_pixels(const RenderJob& a, const RenderJob& b) {
    return a.width == b.width && a.height == b.height && a.render_region() == b.render_region() &&
           a.camera == b.camera && a.integrator == b.integrator && a.sampling == b.sampling &&
           a.sample_begin == b.sample_begin && a.sample_end == b.sample_end && a.active == b.active;
}

RenderStats render(const Integrator& integrator, const RenderJob& job, Film& film) {
    return render_tiles(integrator, job, cut_into_tiles(job.render_region(), job.tile_size), film);
}

namespace {

// The tile loop: each worker adds the job's samples of a tile to the film film_for(worker, tile)
// gives, then finish(worker, tile, film) sees it (also when a cancel cut it short).
template <class FilmFor, class Finish>
RenderStats run_tiles(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                      int threads, FilmFor&& film_for, Finish&& finish) {
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    stats.tiles_total = int(tiles.size());
    stats.threads = threads;
    // Work the integrator does once for these samples (a photon pass), on the job's threads: the
    // same samples as every tile's (TileRenderer's range), so every MPI rank prepares the same.
    const int n = job.sampling.samples_per_pixel();
    SampleRange range;
    range.begin = std::clamp(job.sampling.adaptive() ? 0 : job.sample_begin, 0, n);
    range.end = job.sampling.adaptive() || job.sample_end < 0 ? n : std::clamp(job.sample_end, range.begin, n);
    range.seed = job.sampling.seed;
    range.threads = job.threads;
    range.cancel = job.cancel;
    if (!tiles.empty() && !integrator.prepare(range)) {
        stats.cancelled = true;
        stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        return stats;
    }

    // One renderer (scratch buffers, ray counts) per worker, each on cache lines of its own.
    std::vector<TileRenderer> workers;
    workers.reserve(std::size_t(stats.threads));
    for (int w = 0; w < stats.threads; ++w) workers.emplace_back(integrator, job);
    alignas(64) std::atomic<int> done{0};
    parallel_for(tiles.size(), stats.threads, [&](std::size_t i, int w) {
        if (job.cancel && job.cancel->load(std::memory_order_relaxed)) return;
        Film& film = film_for(w, tiles[i]);
        const bool complete = workers[std::size_t(w)].render(tiles[i], film);
        finish(w, tiles[i], film);
        if (!complete) return;
        done.fetch_add(1, std::memory_order_relaxed);
        if (job.on_tile) job.on_tile(tiles[i]);
    });
    for (const TileRenderer& w : workers) stats.rays += w.counts();

    stats.tiles_done = done.load();
    stats.cancelled = stats.tiles_done < stats.tiles_total;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace

RenderStats render_tiles(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                         Film& film) {
    return run_tiles(
        integrator, job, tiles, worker_count(job.threads, tiles.size()),
        [&](int, const Tile&) -> Film& { return film; }, [](int, const Tile&, const Film&) {});
}

RenderStats render_tiles_into(const Integrator& integrator, const RenderJob& job, const std::vector<Tile>& tiles,
                              const std::function<Film&(const Tile&)>& film_for) {
    return run_tiles(
        integrator, job, tiles, worker_count(job.threads, tiles.size()),
        [&](int, const Tile& t) -> Film& { return film_for(t); }, [](int, const Tile&, const Film&) {});
}

RenderStats render(const Scene& scene, const RenderJob& job, Image& image) {
    const auto integrator = make_integrator(scene, job.camera_for(scene), job.integrator);
    // Each worker adds a tile's samples to a small film of its own and writes the tile's bytes: a
    // film of the whole image would be 16 bytes a pixel to fault in and convert (a tenth of a
    // one-sample 1080p render).
    const std::vector<Tile> tiles = cut_into_tiles(job.render_region(), job.tile_size);
    const int threads = worker_count(job.threads, tiles.size());
    std::vector<Film> tile_films(static_cast<std::size_t>(threads));
    return run_tiles(
        *integrator, job, tiles, threads,
        [&](int w, const Tile& t) -> Film& {
            tile_films[std::size_t(w)].reset(job.width, job.height, t);
            return tile_films[std::size_t(w)];
        },
        [&](int, const Tile& t, const Film& film) { film.write_to(image, t); });
}

}  // namespace whitted
