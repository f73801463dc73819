#pragma once
// How the pixels of one tile get their samples: camera rays generated for (pixel, sample index),
// traced a packet at a time through the integrator, added to the film in sample order. One
// sample per pixel: packets of 4 × 4 neighbouring pixels; several: a row's pixels one after
// another, their samples in order. Adaptive anti-aliasing: every pixel's centre first (the tile
// and a pixel around it), then all samples only where a centre differs from a neighbour's.
// Every pixel depends only on its coordinates and sample indices, never on the tiles rendered
// before, so the image is the same for any thread count and tile order.
#include <atomic>
#include <vector>

#include "film/film.h"
#include "integrator/integrator.h"
#include "render/render_job.h"

namespace whitted {

// The camera rays of one sample per pixel are traced in packets of kPacketWidth × kPacketHeight
// neighbouring pixels.
constexpr int kPacketWidth = 4;
constexpr int kPacketHeight = kPacketSize / kPacketWidth;

// The camera ray of sample `index` of pixel (x, y) of a width × height image, drawn from
// `sampler`: what every renderer traces (and the pixel inspector traces again). `timed`: the
// scene moves during the shutter (Scene::motion), so the ray takes the sample's time too.
Ray camera_sample_ray(const Camera& camera, const Sampler& sampler, int width, int height, int x, int y,
                      std::uint32_t index, bool timed = false);

class TileRenderer {
public:
    // One per worker thread; allocates its buffers here, for tiles up to the job's tile size.
    TileRenderer(const Integrator& integrator, const RenderJob& job);

    // Adds the job's samples of the pixels of tile t to `film`. Checks the job's cancel flag
    // before every packet of samples; returns false (the tile left unfinished) once it is set.
    bool render(const Tile& t, Film& film);

    const RayCounts& counts() const { return counts_; }

private:
    bool stop_requested() const;
    // The colour a sample adds to the film: clamped if the integrator asks for it; otherwise a
    // sample that is not finite is counted and adds black.
    glm::vec3 displayed(const glm::vec3& c);
    // Camera ray of sample `index` of pixel (x, y), drawn from `sampler`.
    Ray camera_ray(const Sampler& sampler, int x, int y, std::uint32_t index) const;
    // The colours of sample `index` of rows [y0, y0 + kPacketHeight) of `region`, from `sampler`,
    // into band_.
    bool trace_band(const Sampler& sampler, const Tile& region, int y0, std::uint32_t index);
    glm::vec3& band_at(const Tile& region, int x, int y);
    // Adds samples [s0, s1) of pixels xs_[0 .. n) of row y to the film (false: cancelled part-way).
    bool add_samples(int y, int n, int s0, int s1, Film& film);
    // The job's active-pixel mask: whether pixel (x, y) takes samples.
    bool active(int x, int y) const;
    // Adaptive: true when pixel (x, y)'s centre colour differs from a neighbour's in `apron`.
    bool differs(const Tile& apron, int x, int y) const;
    glm::vec3& centre_at(const Tile& apron, int x, int y);
    const glm::vec3& centre_at(const Tile& apron, int x, int y) const;

    const Integrator& integrator_;
    const RenderJob& job_;
    Camera camera_;
    Sampler sampler_;
    Sampler centre_sampler_;  // one sample per pixel: every centre (adaptive's first look)
    bool clamp_;
    bool timed_;  // the scene moves during the shutter: camera rays take a time each
    int s0_, s1_;
    int band_y0_ = 0, band_w_;
    std::vector<glm::vec3> band_;     // band_w_ × kPacketHeight colours of one sample
    std::vector<glm::vec3> centres_;  // adaptive: the apron's centre colours, clamped
    std::vector<int> xs_;             // the pixels of a row to sample
    alignas(64) RayCounts counts_;
};

}  // namespace whitted
