#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace whitted {

RenderStats render(const Scene& scene, const RenderOptions& options, Image& image) {
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    const int w = image.width, h = image.height, ts = std::max(1, options.tile_size);
    std::vector<Tile> tiles;
    for (int y = 0; y < h; y += ts)
        for (int x = 0; x < w; x += ts) tiles.push_back({x, y, std::min(x + ts, w), std::min(y + ts, h)});
    stats.tiles_total = int(tiles.size());

    const WhittedIntegrator shared_integrator(scene, {options.max_depth, options.mode});
    // The counters every worker writes get cache lines of their own (no false sharing with what
    // the workers read per pixel).
    alignas(64) std::atomic<int> next{0};
    alignas(64) std::atomic<int> done{0};
    std::mutex stats_mutex;

    auto worker = [&] {
        // Per-thread copies of what is read per pixel, and the ray counts on their own line.
        const WhittedIntegrator integrator = shared_integrator;
        const Camera camera = scene.flat.camera;
        alignas(64) RayCounts counts;
        TileSampler sampler(integrator, camera, w, h, ts, {options.aa, options.aa_threshold});
        for (int i; (i = next.fetch_add(1)) < int(tiles.size());) {
            const Tile& t = tiles[i];
            const bool complete = sampler.render(t, image, counts, options.cancel);
            if (!complete) break;
            ++done;
            if (options.on_tile) options.on_tile(t);
        }
        std::lock_guard lock(stats_mutex);
        stats.rays += counts;
    };

    int n = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    n = std::min(n, std::max(1, int(tiles.size())));
    stats.threads = n;
    std::vector<std::thread> pool;
    for (int i = 1; i < n; ++i) pool.emplace_back(worker);
    worker();
    for (auto& t : pool) t.join();

    stats.tiles_done = done.load();
    stats.cancelled = stats.tiles_done < stats.tiles_total;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace whitted
