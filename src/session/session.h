#pragma once
// A render session: one scene, one RenderJob, and the schedule that renders it in passes over the
// whole image, as Cycles' Session and RenderScheduler do. The CLI, the viewer and whitted-mpi all
// drive one; none keeps a render loop of its own.
//
// Passes: one sample per sub-pixel cell first (aa × aa per pixel), then each pass doubles the
// samples done, up to the job's samples per pixel; adaptive anti-aliasing is one pass. The film
// holds the last whole pass while the next one renders (each tile continues from it into a second
// film): a cancel or a time budget keeps a complete image at the samples reached, in tile order
// only during the first pass. Samples are added to every pixel in index order, so the bytes are
// those of a render of that many samples in one go, for any thread count and tile size.
//
// A noise threshold (as Cycles' adaptive sampling) stops each pixel once its error estimate, from
// its mean after the last pass against its mean after the one before (the other film holds it), is
// below the threshold in its whole 3 × 3 neighbourhood; checked between passes from a minimum of
// samples, so the result does not depend on threads or tiles either.
#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <memory>
#include <vector>

#include "film/channel_film.h"
#include "film/film.h"
#include "render/aov.h"
#include "render/render_job.h"
#include "render/renderer.h"
#include "session/pass_renderer.h"

namespace whitted {

struct Scene;
class Integrator;

// The sample index each pass of `sampling` ends at.
std::vector<int> sample_passes(const SamplingSettings& sampling);

// The resolutions of the coarse frames a moving camera gets before the full image, as divisors.
inline constexpr int kPreviewDivisors[] = {8, 4, 2};

// Adaptive sampling's error estimate of a pixel of n samples, from the same pixel when it had its
// first m < n: with A the mean of the first m and B of the other n − m, the difference of the two
// means is (n − m)/n · (B − A), which estimates the standard error of the whole mean once scaled by
// sqrt(m / (n − m)) (1 for the halves of a doubling pass). Both parts are power-of-two blocks of the
// pixel's stratified samples (sampler/sampler.h), so the estimate stays honest where plain
// variance would overstate stratified error many times. Summed over the channels and divided by
// the square root of the pixel's brightness (noise in dark pixels is seen more, as Cycles weighs
// it). Infinite without an earlier part to compare with.
float pixel_error_estimate(const FilmPixel& now, const FilmPixel& before);

// What a pass did.
struct PassStats {
    RenderStats render;       // of this pass's tiles
    int samples_begin = 0, samples_end = 0;
    std::size_t pixels = 0;   // pixels that took samples in this pass (adaptive: those not yet converged)
};

class Session {
public:
    // Renders `scene` as `job` says: its size, region, camera, integrator, sampling, threads, tile
    // size and cancel flag (job.sample_begin and sample_end are the session's to set).
    Session(std::shared_ptr<const Scene> scene, const RenderJob& job);
    // With job.aovs, the per-term images too (render/aov.h), over the same samples as the image;
    // the job must have passed aov_problem (a std::invalid_argument otherwise).
    // `renderer` (optional, outliving the session) renders the passes' tiles instead of this
    // process's threads (whitted-mpi's ranks); not with job.aovs.
    Session(std::shared_ptr<const Scene> scene, const RenderJob& job, PassRenderer* renderer);
    ~Session();
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

    const RenderJob& job() const { return job_; }
    const Scene& scene() const { return *scene_; }
    const Integrator& integrator() const { return *integrator_; }

    // The schedule and how far it went.
    const std::vector<int>& pass_ends() const { return passes_; }
    int passes_done() const { return passes_done_; }
    int samples_done() const { return passes_done_ == 0 ? 0 : passes_[std::size_t(passes_done_ - 1)]; }
    bool done() const { return passes_done_ == int(passes_.size()); }

    // Renders the next pass. Called from one thread at a time; `on_tile` (optional) is called from
    // worker threads with each finished tile and the film holding its new pixels (read them there:
    // the film is written by other workers at the same time, in other tiles). When the job's cancel
    // flag stops it, the pass is dropped: film() keeps the last whole pass (during the first pass:
    // the tiles finished). Returns the pass's statistics.
    PassStats render_pass(const std::function<void(const Tile&, const Film&)>& on_tile = {});

    // Continues a render stopped part-way (a checkpoint, session/checkpoint.h): `whole` (the whole
    // image) holds the first `passes` passes, and `next` the pass after them in the tiles that
    // `next_done` marks (indices into tiles()), which the next render_pass does not render again.
    // Not with a noise threshold (which pixels have stopped is not given).
    void resume(int passes, const Film& whole, const Film& next, const std::vector<bool>& next_done);
    // The tiles each pass renders, in order.
    const std::vector<Tile>& tiles() const { return tiles_; }

    // The time the next pass is expected to take, from the passes so far (0 before the first):
    // the last pass's time scaled by its samples and pixels (a time budget's forecast).
    double forecast_next_pass_seconds() const;

    // The image so far: the last whole pass (or the first pass's finished tiles).
    const Film& film() const { return *shown_; }
    // The per-term images (null without job.aovs) and their floats for the image film() holds.
    const AovPlan* aov_plan() const { return aov_plan_.get(); }
    const ChannelFilm& aov_film() const { return aov_films_[shown_ == &films_[0] ? 0 : 1]; }
    // Samples each pixel of the job's region took (adaptive sampling; else every pixel the same).
    std::vector<int> samples_per_pixel() const;

    // A coarse frame for a moving camera: the job's camera at 1/divisor of the size (the aspect
    // kept as well as whole pixels allow), one sample per pixel, enlarged (nearest) to the job's
    // size: its mean colours, unclamped. Returns false if cancelled.
    bool render_preview(int divisor, LinearImage& out) const;

    // The sum of the rays of every pass so far.
    const RayCounts& rays() const { return rays_; }
    double seconds() const { return seconds_; }  // rendering time of every pass so far

private:
    void update_convergence();

    std::shared_ptr<const Scene> scene_;
    RenderJob job_;
    std::unique_ptr<Integrator> integrator_;
    PassRenderer* renderer_ = nullptr;
    std::vector<int> passes_;
    int passes_done_ = 0;
    std::vector<Tile> tiles_;
    std::vector<bool> resumed_;  // tiles of the next pass already done (resume)
    Film films_[2];
    Film* shown_ = &films_[0];  // the last whole pass
    std::unique_ptr<AovPlan> aov_plan_;
    ChannelFilm aov_films_[2];  // beside films_[0] and films_[1]
    std::vector<std::uint8_t> active_;  // adaptive: 1 = the pixel takes the next pass's samples
    std::vector<std::uint16_t> converged_at_;  // adaptive: the pass count at which the pixel stopped (0 = never)
    PassStats last_;
    RayCounts rays_;
    double seconds_ = 0;
};

// Why `job` cannot render its per-term images of `scene` ("" = it can, or asks for none): a layer
// the scene has no light for, the course's lighting model, adaptive anti-aliasing, or more memory
// than `max_bytes` for their floats (two films of them while passes render, and the layers written).
std::string aov_problem(const Scene& scene, const RenderJob& job, std::size_t max_bytes = SIZE_MAX);

// The nearest-neighbour enlargement of `small` to width × height (a coarse frame shown full size).
Image enlarge_nearest(const Image& small, int width, int height);
LinearImage enlarge_nearest(const LinearImage& small, int width, int height);

}  // namespace whitted
