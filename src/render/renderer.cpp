#include "render/renderer.h"

#include <algorithm>
#include <chrono>
#include <mutex>
#include <thread>
#include <vector>

namespace whitted {

Ray camera_ray(const Camera& cam, int width, int height, float x, float y) {
    const float aspect = float(width) / float(height);
    const float sx = (2.0f * x / float(width) - 1.0f) * cam.tan_half_fov * aspect;
    const float sy = (1.0f - 2.0f * y / float(height)) * cam.tan_half_fov;
    return Ray{cam.eye, glm::normalize(cam.forward + sx * cam.right + sy * cam.up)};
}

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
    auto cancelled = [&] { return options.cancel && options.cancel->load(std::memory_order_relaxed); };

    auto worker = [&] {
        // Per-thread copies of what is read per pixel, and the ray counts on their own line.
        const WhittedIntegrator integrator = shared_integrator;
        const Camera camera = scene.flat.camera;
        alignas(64) RayCounts counts;
        for (int i; (i = next.fetch_add(1)) < int(tiles.size());) {
            const Tile& t = tiles[i];
            bool complete = true;
            for (int y = t.y0; y < t.y1 && complete; ++y) {
                if (cancelled()) { complete = false; break; }
                for (int x = t.x0; x < t.x1; ++x) {
                    glm::vec3 c = integrator.camera_ray(camera_ray(camera, w, h, x + 0.5f, y + 0.5f), counts);
                    std::uint8_t* p = &image.rgb[(std::size_t(y) * w + x) * 3];
                    p[0] = to_byte(c.x);
                    p[1] = to_byte(c.y);
                    p[2] = to_byte(c.z);
                }
            }
            if (!complete) break;
            ++done;
            if (options.on_tile) options.on_tile(t);
        }
        std::lock_guard lock(stats_mutex);
        stats.rays += counts;
    };

    int n = options.threads > 0 ? options.threads : int(std::max(1u, std::thread::hardware_concurrency()));
    n = std::min(n, std::max(1, int(tiles.size())));
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
