#pragma once
// Image-space driver: cuts the image into tiles, hands them to worker threads (each with its own
// TileSampler), and stops when asked. Every pixel depends only on its own coordinates, so the
// image is the same for any thread count.
#include <atomic>
#include <functional>

#include "accel/bvh_packet.h"
#include "accel/scene.h"
#include "film/image.h"
#include "integrator/whitted_integrator.h"
#include "render/tile_sampler.h"

namespace whitted {

struct RenderOptions {
    int width = 640, height = 480;
    int max_depth = 5;
    RenderMode mode = RenderMode::Whitted;
    int aa = 1;                 // anti-aliasing: aa × aa rays per pixel (see Sampling)
    float aa_threshold = 0.0f;  // > 0: only where neighbours differ by more (see Sampling)
    int threads = 0;            // 0 = all hardware threads
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

}  // namespace whitted
