#pragma once
// How the pixels of one tile get their colours: one camera ray through each pixel centre, or
// anti-aliased with aa × aa rays per pixel, everywhere or (adaptive) only where a pixel's centre
// colour differs from a neighbour's. Camera rays are traced a packet at a time. Every pixel
// depends only on its coordinates, never on which tiles were rendered before, so the image is
// the same for any thread count and tile order.
#include <atomic>
#include <vector>

#include "accel/bvh_packet.h"
#include "film/image.h"
#include "integrator/whitted_integrator.h"

namespace whitted {

// The camera rays are traced in packets of kPacketWidth × kPacketHeight neighbouring pixels.
constexpr int kPacketWidth = 4;
constexpr int kPacketHeight = kPacketSize / kPacketWidth;
constexpr int kMaxAa = 16;  // aa × aa rays per pixel: 256 at the most

struct Tile {
    int x0, y0, x1, y1;  // pixels [x0, x1) × [y0, y1)
};

struct Sampling {
    // aa × aa rays per pixel through the centres of a regular grid of sub-pixels, each colour
    // clamped to [0, 1] before their mean is taken; 1 = one ray through the pixel centre.
    int aa = 1;
    // Adaptive anti-aliasing: > 0 supersamples only the pixels whose centre colour differs from
    // one of its four neighbours' by more than this in some channel (colours clamped to [0, 1]);
    // the others keep their centre ray. 0 supersamples every pixel.
    float threshold = 0.0f;
};

// The camera ray through the point (x, y) of the image plane, in pixels from the top left
// corner (a pixel's centre is at +0.5); row 0 is the top.
Ray camera_ray(const Camera& camera, int width, int height, float x, float y);

class TileSampler {
public:
    // One per worker thread; allocates its buffers here, for tiles up to tile_size square.
    TileSampler(const WhittedIntegrator& integrator, const Camera& camera, int image_w, int image_h, int tile_size,
                const Sampling& sampling);

    // Renders tile t into `image`. Checks `cancel` before every row; returns false (the tile
    // left unfinished) once it is set.
    bool render(const Tile& t, Image& image, RayCounts& counts, const std::atomic<bool>* cancel);

private:
    // The colours of rows [y0, y0 + kPacketHeight) of `region` seen through the pixel centres,
    // traced and shaded a packet at a time.
    void trace_band(const Tile& region, int y0, RayCounts& counts);
    glm::vec3& band_at(const Tile& region, int x, int y);
    // Mean colours of pixels xs[0 .. n) of row y (into means_), aa × aa rays each.
    void supersample(int y, int n, RayCounts& counts);
    // True when pixel (x, y)'s centre colour differs from a neighbour's in `apron` (the tile
    // and the pixels around it) by more than the threshold.
    bool differs(const Tile& apron, int x, int y) const;
    glm::vec3& centre_at(const Tile& apron, int x, int y);
    const glm::vec3& centre_at(const Tile& apron, int x, int y) const;

    const WhittedIntegrator& integrator_;
    const Camera& camera_;
    int image_w_, image_h_, band_w_;
    Sampling sampling_;
    int band_y0_ = 0;
    std::vector<glm::vec3> band_;       // band_w_ × kPacketHeight centre colours
    std::vector<glm::vec3> centres_;    // adaptive: the apron's centre colours, clamped
    std::vector<int> xs_;               // the pixels of a row to supersample
    std::vector<glm::vec3> means_;      // their colours
};

}  // namespace whitted
