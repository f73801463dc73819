#include "render/aov_renderer.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>

#include "accel/scene.h"
#include "base/parallel_for.h"
#include "integrator/path_integrator.h"
#include "integrator/whitted_integrator.h"
#include "render/tile_renderer.h"

namespace whitted {
namespace {

// One worker's state: the sample record (its per-light arrays sized once) and its ray counts.
class AovTileRenderer {
public:
    AovTileRenderer(const Integrator& integrator, const RenderJob& job, const AovPlan& plan)
        : integrator_(integrator), job_(job), plan_(plan),
          whitted_(dynamic_cast<const WhittedIntegrator*>(&integrator)),
          path_(dynamic_cast<const PathIntegrator*>(&integrator)), camera_(integrator.camera()),
          sampler_(job.sampling.aa, job.sampling.spp, job.sampling.seed), clamp_(integrator.clamps_samples()) {
        const int n = sampler_.samples_per_pixel();
        s0_ = std::clamp(job.sample_begin, 0, n);
        s1_ = job.sample_end < 0 ? n : std::clamp(job.sample_end, s0_, n);
        sample_.size_lights(plan.lights());
        counts_.timing = job.time_rays;
    }

    bool render(const Tile& t, Film& film, ChannelFilm& aov) {
        const PixelRegion r = job_.render_region();
        for (int y = t.y0; y < t.y1; ++y)
            for (int x = t.x0; x < t.x1; ++x) {
                if (job_.cancel && job_.cancel->load(std::memory_order_relaxed)) return false;
                if (job_.active &&
                    !(*job_.active)[std::size_t(y - r.y0) * std::size_t(r.width()) + std::size_t(x - r.x0)])
                    continue;
                for (int i = s0_; i < s1_; ++i) add_sample(x, y, std::uint32_t(i), film, aov);
            }
        return true;
    }

    const RayCounts& counts() const { return counts_; }

private:
    void add_sample(int x, int y, std::uint32_t index, Film& film, ChannelFilm& aov) {
        const SampleKey key{std::uint32_t(x), std::uint32_t(y), index};
        const Ray ray = camera_sample_ray(camera_, sampler_, job_.width, job_.height, x, y, index,
                                          !integrator_.scene().motion.empty());
        sample_.clear();
        glm::vec3 c(0.0f);
        if (whitted_) {
            AovRecorder recorder(sample_);
            c = whitted_->radiance(ray, key, sampler_, counts_, recorder);
        } else {
            // The first hit found here is the path's own (it is handed to the path tracer).
            Hit hit;
            const bool found =
                timed_trace(counts_, RayKind::Camera, 1, [&] { return integrator_.scene().intersect(ray, hit); });
            if (found) {
                const Surface s = surface_at(integrator_.scene(), ray, hit);
                sample_.hit = true;
                sample_.instance = hit.instance;
                sample_.normal = s.normal;
                sample_.albedo = s.diffuse;
                sample_.depth = hit.t * glm::length(ray.direction);
            }
            glm::vec3 direct(0.0f);
            c = path_->radiance(ray, key, sampler_, counts_, found ? &hit : nullptr, true, &direct);
            sample_.direct = direct;
            sample_.indirect = c - direct;
        }
        // What the film gets, as TileRenderer gives it: clamped (§7), or a sample that is not
        // finite counted and added as black (its layers then add nothing either).
        if (clamp_) {
            film.add(x, y, {clamp01(c.x), clamp01(c.y), clamp01(c.z)});
        } else if (std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z)) {
            film.add(x, y, c);
        } else {
            ++counts_.rejected;
            film.add(x, y, glm::vec3(0.0f));
            sample_.direct = sample_.indirect = glm::vec3(0.0f);
        }
        const float d = sampler_.centred() ? 0.0f : glm::length(sampler_.pixel_offset(key) - glm::vec2(0.5f));
        plan_.add(aov.at(x, y), sample_, d);
    }

    const Integrator& integrator_;
    const RenderJob& job_;
    const AovPlan& plan_;
    const WhittedIntegrator* whitted_;
    const PathIntegrator* path_;
    Camera camera_;
    Sampler sampler_;
    bool clamp_;
    int s0_ = 0, s1_ = 0;
    AovSample sample_;
    alignas(64) RayCounts counts_;
};

}  // namespace

std::string aov_refusal(const Integrator& integrator) {
    if (dynamic_cast<const WhittedIntegrator*>(&integrator) || dynamic_cast<const PathIntegrator*>(&integrator))
        return "";
    return "per-term images (--aov) are rendered for the lab's Whitted model and path tracing; not yet for a CSCI "
           "1230 scene's lighting model";
}

RenderStats render_tiles_with_aovs(const Integrator& integrator, const RenderJob& job, const AovPlan& plan,
                                   const std::vector<Tile>& tiles, const std::function<Film&(const Tile&)>& film_for,
                                   const std::function<ChannelFilm&(const Tile&)>& aov_for) {
    const auto start = std::chrono::steady_clock::now();
    RenderStats stats;
    stats.tiles_total = int(tiles.size());
    stats.threads = worker_count(job.threads, tiles.size());
    std::vector<AovTileRenderer> workers;
    workers.reserve(std::size_t(stats.threads));
    for (int w = 0; w < stats.threads; ++w) workers.emplace_back(integrator, job, plan);
    alignas(64) std::atomic<int> done{0};
    parallel_for(tiles.size(), stats.threads, [&](std::size_t i, int w) {
        if (job.cancel && job.cancel->load(std::memory_order_relaxed)) return;
        Film& film = film_for(tiles[i]);
        ChannelFilm& aov = aov_for(tiles[i]);
        if (!workers[std::size_t(w)].render(tiles[i], film, aov)) return;
        done.fetch_add(1, std::memory_order_relaxed);
        if (job.on_tile) job.on_tile(tiles[i]);
    });
    for (const AovTileRenderer& w : workers) stats.rays += w.counts();
    stats.tiles_done = done.load();
    stats.cancelled = stats.tiles_done < stats.tiles_total;
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
}

}  // namespace whitted
