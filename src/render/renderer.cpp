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

namespace {

// The camera rays of a band of kPacketHeight rows of a tile and their nearest hits, found a
// packet of kPacketWidth × kPacketHeight pixels at a time (the packet's rays are neighbours, so
// they share most of their way through the BVH). Shading then goes row by row as before.
class CameraBand {
public:
    struct Pixel {
        Ray ray;
        Hit hit;
        bool found;
    };

    // For tiles up to `max_width` pixels wide; the only allocation, once per worker.
    explicit CameraBand(int max_width) : width_(max_width), pixels_(std::size_t(max_width) * kPacketHeight) {}

    // Traces the rows [y0, y0 + kPacketHeight) of tile t, cut at its bottom edge (packets cut by
    // the tile's edges leave their outside lanes off).
    void trace(const WhittedIntegrator& integrator, const Camera& camera, int image_w, int image_h, const Tile& t,
               int y0) {
        y0_ = y0;
        for (int x0 = t.x0; x0 < t.x1; x0 += kPacketWidth) {
            Ray rays[kPacketSize];
            unsigned active = 0;
            for (int l = 0; l < kPacketSize; ++l) {
                const int x = x0 + l % kPacketWidth, y = y0 + l / kPacketWidth;
                if (x >= t.x1 || y >= t.y1) continue;
                rays[l] = camera_ray(camera, image_w, image_h, x + 0.5f, y + 0.5f);
                active |= 1u << l;
            }
            Hit hits[kPacketSize];
            const unsigned found = integrator.camera_hits(rays, active, hits);
            for (int l = 0; l < kPacketSize; ++l) {
                if (!((active >> l) & 1)) continue;
                Pixel& p = at(x0 - t.x0 + l % kPacketWidth, y0 + l / kPacketWidth);
                p.ray = rays[l];
                p.found = (found >> l) & 1;
                if (p.found) p.hit = hits[l];
            }
        }
    }

    // Pixel (x - tile's x0, y) of the band last traced.
    Pixel& at(int tile_x, int y) { return pixels_[std::size_t(y - y0_) * width_ + tile_x]; }

private:
    int width_, y0_ = 0;
    std::vector<Pixel> pixels_;
};

// Anti-aliased colours of one row of a tile: aa × aa camera rays per pixel through the centres
// of its sub-pixels. The row's rays, pixel after pixel and sub-pixel row by row within each, are
// cut into packets in that order, so a packet covers neighbouring sub-pixels whatever aa is.
class SupersampledRow {
public:
    // For tiles up to `max_width` pixels wide; the only allocation, once per worker.
    SupersampledRow(int max_width, int aa) : aa_(aa), sums_(std::size_t(max_width)) {}

    // The mean colour of pixels [t.x0, t.x1) of row y, left to right.
    const std::vector<glm::vec3>& trace(const WhittedIntegrator& integrator, const Camera& camera, int image_w,
                                        int image_h, const Tile& t, int y, RayCounts& counts) {
        const int per_pixel = aa_ * aa_, total = (t.x1 - t.x0) * per_pixel;
        const float step = 1.0f / float(aa_);
        std::fill(sums_.begin(), sums_.end(), glm::vec3(0.0f));
        for (int k0 = 0; k0 < total; k0 += kPacketSize) {
            const int lanes = std::min(kPacketSize, total - k0);
            Ray rays[kPacketSize];
            for (int l = 0; l < lanes; ++l) {
                const int k = k0 + l, pixel = k / per_pixel, sub = k % per_pixel;
                rays[l] = camera_ray(camera, image_w, image_h, float(t.x0 + pixel) + (float(sub % aa_) + 0.5f) * step,
                                     float(y) + (float(sub / aa_) + 0.5f) * step);
            }
            const unsigned active = (1u << lanes) - 1;
            Hit hits[kPacketSize];
            const unsigned found = integrator.camera_hits(rays, active, hits);
            for (int l = 0; l < lanes; ++l) {
                const glm::vec3 c = integrator.camera_ray(rays[l], (found >> l) & 1 ? &hits[l] : nullptr, counts);
                sums_[std::size_t((k0 + l) / per_pixel)] += glm::vec3(clamp01(c.x), clamp01(c.y), clamp01(c.z));
            }
        }
        for (glm::vec3& s : sums_) s /= float(per_pixel);
        return sums_;
    }

private:
    int aa_;
    std::vector<glm::vec3> sums_;
};

void store(Image& image, int x, int y, const glm::vec3& c) {
    std::uint8_t* p = &image.rgb[(std::size_t(y) * image.width + x) * 3];
    p[0] = to_byte(c.x);
    p[1] = to_byte(c.y);
    p[2] = to_byte(c.z);
}

}  // namespace

RenderStats render(const Scene& scene, const RenderOptions& options, Image& image) {
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    const int w = image.width, h = image.height, ts = std::max(1, options.tile_size);
    const int aa = std::clamp(options.aa, 1, kMaxAa);
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
        const int row_w = std::min(ts, w);
        CameraBand band(aa == 1 ? row_w : 0);
        SupersampledRow supersampled(aa == 1 ? 0 : row_w, aa);
        for (int i; (i = next.fetch_add(1)) < int(tiles.size());) {
            const Tile& t = tiles[i];
            bool complete = true;
            for (int y = t.y0; y < t.y1 && complete; ++y) {
                if (cancelled()) { complete = false; break; }
                if (aa > 1) {
                    const auto& row = supersampled.trace(integrator, camera, w, h, t, y, counts);
                    for (int x = t.x0; x < t.x1; ++x) store(image, x, y, row[std::size_t(x - t.x0)]);
                    continue;
                }
                if ((y - t.y0) % kPacketHeight == 0) band.trace(integrator, camera, w, h, t, y);
                for (int x = t.x0; x < t.x1; ++x) {
                    const CameraBand::Pixel& px = band.at(x - t.x0, y);
                    store(image, x, y, integrator.camera_ray(px.ray, px.found ? &px.hit : nullptr, counts));
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
