#pragma once
// Image-space driver: cuts the image into tiles, hands them to worker threads, and stops when
// asked. Every pixel depends only on its own ray, so the image is the same for any thread count.
#include <atomic>
#include <functional>

#include "accel/bvh_packet.h"
#include "accel/scene.h"
#include "film/image.h"
#include "integrator/whitted_integrator.h"

namespace whitted {

// The camera rays are traced in packets of kPacketWidth × kPacketHeight neighbouring pixels.
constexpr int kPacketWidth = 4;
constexpr int kPacketHeight = kPacketSize / kPacketWidth;
constexpr int kMaxAa = 16;  // --aa range: 256 rays per pixel at most

struct Tile {
    int x0, y0, x1, y1;  // pixels [x0, x1) × [y0, y1)
};

struct RenderOptions {
    int width = 640, height = 480;
    int max_depth = 5;
    RenderMode mode = RenderMode::Whitted;
    // Anti-aliasing: aa × aa camera rays per pixel through the centres of a regular grid of
    // sub-pixels, each colour clamped to [0, 1] before their mean is taken. 1 = one ray through
    // the pixel centre.
    int aa = 1;
    int threads = 0;     // 0 = all hardware threads
    int tile_size = 32;
    // Set by another thread (or a signal handler) to stop; checked at least once per tile row.
    const std::atomic<bool>* cancel = nullptr;
    // Called from worker threads as each tile is finished (must be thread-safe).
    std::function<void(const Tile&)> on_tile;
};

struct RenderStats {
    RayCounts rays;
    double seconds = 0;
    int tiles_done = 0, tiles_total = 0;
    int threads = 0;  // worker threads used (never more than there are tiles)
    bool cancelled = false;  // pixels of unfinished tiles are left as they were (black in a new image)
};

// Renders into `image`, which must already have the options' size (pixels of tiles not reached
// before a cancel are left untouched).
RenderStats render(const Scene& scene, const RenderOptions& options, Image& image);

// The camera ray through the centre of pixel (x, y); row 0 is the top.
Ray camera_ray(const Camera& camera, int width, int height, float x, float y);

}  // namespace whitted
