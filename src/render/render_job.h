#pragma once
// One render, described once: what the front ends (CLI, viewer, MPI ranks) ask of the renderer.
// The image size, the part of it to render, which samples, how, and how to report. Settings only:
// it names the scene without including it.
#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "camera/camera.h"
#include "film/pixel_region.h"
#include "integrator/integrator_settings.h"
#include "sampler/sampler.h"

namespace whitted {

struct Scene;  // accel/scene.h

using Tile = PixelRegion;

// How many samples each pixel gets and where: aa × aa sub-pixel cells, spp samples in each
// (sampler/sampler.h); adaptive anti-aliasing as POV-Ray's +A.
struct SamplingSettings {
    int aa = 1;   // 1..Sampler::kMaxAa
    int spp = 1;  // samples per cell, 1..Sampler::kMaxSpp
    // > 0 (with aa > 1 and spp = 1): each pixel's centre first; only the pixels whose centre colour
    // differs from one of its four neighbours' by more than this in some channel (colours clamped
    // to [0, 1]) get their aa × aa samples, the others keep their centre. 0 = every pixel.
    float aa_threshold = 0.0f;
    std::uint32_t seed = 0;  // another seed, other (equally good) sample values: independent renders
    // > 0 (a render in passes, render/session.h): a pixel takes no more samples once its error
    // estimate is below this in its whole neighbourhood, checked from min_spp samples on.
    float noise_threshold = 0.0f;
    int min_spp = 16;
    int samples_per_pixel() const { return Sampler(aa, spp).samples_per_pixel(); }
    bool adaptive() const { return aa > 1 && spp == 1 && aa_threshold > 0.0f; }
    bool operator==(const SamplingSettings&) const = default;
};

struct RenderJob {
    int width = 640, height = 480;  // the whole image
    std::optional<PixelRegion> region;  // the part to render (inside the image); none = all of it
    std::optional<Camera> camera;       // none = the scene file's camera
    IntegratorSettings integrator;
    SamplingSettings sampling;
    // The samples of each pixel to take now: [sample_begin, sample_end) of samples_per_pixel()
    // (-1 = to the last). A film that already holds the samples before sample_begin gets the rest
    // added in order, so rendering in passes gives the same bytes as in one go. Adaptive
    // anti-aliasing renders all samples at once.
    int sample_begin = 0, sample_end = -1;
    // The pixels of the render region (row by row) to take samples, 1 each; null = all of them.
    const std::vector<std::uint8_t>* active = nullptr;
    // The per-term images to render beside the image (render/aov.h; a render session makes them):
    // names as --aov lists them; empty = none.
    std::vector<std::string> aovs;
    int threads = 0;  // 0 = all hardware threads
    int tile_size = 32;
    // Time a sample of each kind's traversals (RayCounts::timed) for --stats' rays per second.
    bool time_rays = false;
    // Set by another thread (or a signal handler) to stop; checked at least once per tile row.
    const std::atomic<bool>* cancel = nullptr;
    // Called from worker threads as each tile is finished, its pixels in the film (thread-safe).
    std::function<void(const Tile&)> on_tile;

    PixelRegion render_region() const { return region.value_or(PixelRegion{0, 0, width, height}); }
    Camera camera_for(const Scene& scene) const;  // the job's camera, or the scene file's
    int tile_count() const;
};

// Whether two jobs make the same pixels: the same image, part, camera, method and samples (the
// threads, tile size and callbacks change only how they are made).
bool same_pixels(const RenderJob& a, const RenderJob& b);

}  // namespace whitted
