#include "session/session.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "accel/scene.h"
#include "base/parallel_for.h"
#include "base/read_file.h"
#include "integrator/integrator.h"
#include "render/aov_renderer.h"

namespace whitted {

std::vector<int> sample_passes(const SamplingSettings& sampling) {
    const int n = sampling.samples_per_pixel();
    if (sampling.adaptive()) return {n};
    std::vector<int> ends{std::min(n, Sampler(sampling.aa, 1).samples_per_pixel())};
    while (ends.back() < n) ends.push_back(std::min(n, 2 * ends.back()));
    return ends;
}

Session::Session(std::shared_ptr<const Scene> scene, const RenderJob& job) : Session(std::move(scene), job, nullptr) {}

Session::Session(std::shared_ptr<const Scene> scene, const RenderJob& job, PassRenderer* renderer)
    : scene_(std::move(scene)), job_(job),
      integrator_(make_integrator(*scene_, job.camera_for(*scene_), job.integrator)), renderer_(renderer),
      passes_(sample_passes(job.sampling)), tiles_(cut_into_tiles(job.render_region(), job.tile_size)) {
    job_.on_tile = nullptr;  // the session's own, per pass
    const PixelRegion region = job_.render_region();
    films_[0].reset(job_.width, job_.height, region);
    if (passes_.size() > 1) films_[1].reset(job_.width, job_.height, region);
    if (!job_.aovs.empty()) {
        if (const std::string problem = aov_problem(*scene_, job_); !problem.empty())
            throw std::invalid_argument(problem);
        if (renderer_) throw std::invalid_argument("per-term images (--aov) are rendered by this process only");
        aov_plan_ = std::make_unique<AovPlan>();
        AovPlan::make(job_.aovs, job_.integrator.mode, scene_->data.lights.size(), *aov_plan_);
        aov_films_[0].reset(job_.width, job_.height, region, aov_plan_->channels());
        if (passes_.size() > 1) aov_films_[1].reset(job_.width, job_.height, region, aov_plan_->channels());
    }
    if (job_.sampling.noise_threshold > 0.0f && passes_.size() > 1) {
        const std::size_t pixels = std::size_t(region.width()) * std::size_t(region.height());
        active_.assign(pixels, 1);
        converged_at_.assign(pixels, 0);
    }
}

Session::~Session() = default;

PassStats Session::render_pass(const std::function<void(const Tile&, const Film&)>& on_tile) {
    PassStats pass;
    if (done()) return pass;
    const auto start = std::chrono::steady_clock::now();
    pass.samples_begin = samples_done();
    pass.samples_end = passes_[std::size_t(passes_done_)];
    RenderJob job = job_;
    job.sample_begin = pass.samples_begin;
    job.sample_end = pass.samples_end;
    job.active = active_.empty() ? nullptr : &active_;
    // After a resume, the tiles of this pass not done yet.
    std::vector<Tile> resumed_rest;
    int resumed = 0;
    for (std::size_t i = 0; i < resumed_.size(); ++i) {
        if (resumed_[i])
            ++resumed;
        else
            resumed_rest.push_back(tiles_[i]);
    }
    const std::vector<Tile>& tiles = resumed_.empty() ? tiles_ : resumed_rest;
    pass.pixels = 0;
    if (active_.empty())
        for (const Tile& t : tiles) pass.pixels += std::size_t(t.width()) * std::size_t(t.height());
    else
        pass.pixels = std::size_t(std::count(active_.begin(), active_.end(), std::uint8_t(1)));
    // The first pass renders into the film shown (there is nothing to keep); each later one continues
    // every tile from the last whole pass into the other film, which becomes the one shown once the
    // pass is complete.
    Film& target = passes_done_ == 0 ? *shown_ : (shown_ == &films_[0] ? films_[1] : films_[0]);
    const bool first = passes_done_ == 0;
    job.on_tile = [&](const Tile& t) {
        if (on_tile) on_tile(t, target);
    };
    auto film_for = [&](const Tile& t) -> Film& {
        if (!first) target.copy_from(*shown_, t);
        return target;
    };
    if (aov_plan_) {
        // The layers follow the image: the same tiles continued from the same pass.
        const std::size_t shown = shown_ == &films_[0] ? 0 : 1, into = &target == &films_[0] ? 0 : 1;
        pass.render = render_tiles_with_aovs(*integrator_, job, *aov_plan_, tiles, film_for,
                                             [&](const Tile& t) -> ChannelFilm& {
                                                 if (!first) aov_films_[into].copy_from(aov_films_[shown], t);
                                                 return aov_films_[into];
                                             });
    } else if (renderer_) {
        pass.render = renderer_->render(*integrator_, job, tiles, first ? nullptr : shown_, target);
    } else {
        pass.render = render_tiles_into(*integrator_, job, tiles, film_for);
    }
    pass.render.tiles_done += resumed;
    pass.render.tiles_total = int(tiles_.size());
    rays_ += pass.render.rays;
    seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (pass.render.cancelled) return pass;
    resumed_.clear();
    shown_ = &target;
    ++passes_done_;
    if (!active_.empty()) update_convergence();
    last_ = pass;
    return pass;
}

void Session::resume(int passes, const Film& whole, const Film& next, const std::vector<bool>& next_done) {
    passes_done_ = std::clamp(passes, 0, int(passes_.size()));
    shown_ = &films_[0];
    if (passes_done_ > 0)
        for (const Tile& t : tiles_) films_[0].copy_from(whole, t);
    resumed_.clear();
    if (done()) return;
    // The pass under way renders into the film shown when it is the first, else into the other.
    Film& target = passes_done_ == 0 ? films_[0] : films_[1];
    resumed_.assign(tiles_.size(), false);
    for (std::size_t i = 0; i < tiles_.size() && i < next_done.size(); ++i)
        if (next_done[i]) {
            target.copy_from(next, tiles_[i]);
            resumed_[i] = true;
        }
}

double Session::forecast_next_pass_seconds() const {
    if (passes_done_ == 0 || done() || last_.pixels == 0) return 0.0;
    const double per_sample_pixel = last_.render.seconds / (double(last_.samples_end - last_.samples_begin) *
                                                            double(last_.pixels));
    const std::size_t pixels =
        active_.empty() ? last_.pixels : std::size_t(std::count(active_.begin(), active_.end(), std::uint8_t(1)));
    return per_sample_pixel * double(passes_[std::size_t(passes_done_)] - samples_done()) * double(pixels);
}

float pixel_error_estimate(const FilmPixel& now, const FilmPixel& before) {
    const float n = now.weight, m = before.weight;
    if (!(m > 0.0f && n > m)) return INFINITY;
    const glm::vec3 all = now.sum / n, first = before.sum / m;
    const glm::vec3 d = glm::abs(all - first) * std::sqrt(m / (n - m));
    return (d.x + d.y + d.z) / (1e-4f + std::sqrt(std::max(0.0f, all.x + all.y + all.z)));
}

void Session::update_convergence() {
    if (samples_done() < job_.sampling.min_spp) return;
    const PixelRegion r = job_.render_region();
    const int w = r.width(), h = r.height();
    const Film& before = shown_ == &films_[0] ? films_[1] : films_[0];  // the pass before the last
    std::vector<float> error(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            // A pixel that took no samples in the last pass keeps the estimate that stopped it: 0.
            error[i] = active_[i] ? pixel_error_estimate(shown_->at(r.x0 + x, r.y0 + y), before.at(r.x0 + x, r.y0 + y))
                                  : 0.0f;
        }
    const float threshold = job_.sampling.noise_threshold;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            if (!active_[i]) continue;
            bool converged = true;
            for (int ny = std::max(0, y - 1); ny <= std::min(h - 1, y + 1) && converged; ++ny)
                for (int nx = std::max(0, x - 1); nx <= std::min(w - 1, x + 1); ++nx)
                    if (!(error[std::size_t(ny) * std::size_t(w) + std::size_t(nx)] < threshold)) {
                        converged = false;
                        break;
                    }
            if (converged) {
                active_[i] = 0;
                converged_at_[i] = std::uint16_t(passes_done_);
            }
        }
}

std::vector<int> Session::samples_per_pixel() const {
    const PixelRegion r = job_.render_region();
    std::vector<int> out(std::size_t(r.width()) * std::size_t(r.height()));
    for (int y = r.y0; y < r.y1; ++y)
        for (int x = r.x0; x < r.x1; ++x)
            out[std::size_t(y - r.y0) * std::size_t(r.width()) + std::size_t(x - r.x0)] = int(film().at(x, y).weight);
    return out;
}

bool Session::render_preview(int divisor, LinearImage& out) const {
    RenderJob small = job_;
    small.width = std::max(1, (job_.width + divisor - 1) / divisor);
    small.height = std::max(1, (job_.height + divisor - 1) / divisor);
    small.region.reset();
    small.sampling = SamplingSettings{};
    small.sample_begin = 0;
    small.sample_end = -1;
    small.active = nullptr;
    small.on_tile = nullptr;
    Film film(small.width, small.height);
    if (render(*integrator_, small, film).cancelled) return false;
    out = enlarge_nearest(film.to_linear(), job_.width, job_.height);
    return true;
}

LinearImage enlarge_nearest(const LinearImage& small, int width, int height) {
    LinearImage big{width, height, std::vector<glm::vec3>(std::size_t(width) * std::size_t(height)), {}};
    if (small.width <= 0 || small.height <= 0) return big;
    for (int y = 0; y < height; ++y) {
        const int sy = int(std::int64_t(y) * small.height / height);
        for (int x = 0; x < width; ++x)
            big.rgb[std::size_t(y) * std::size_t(width) + std::size_t(x)] =
                small.rgb[std::size_t(sy) * std::size_t(small.width) + std::size_t(std::int64_t(x) * small.width / width)];
    }
    return big;
}

std::string aov_problem(const Scene& scene, const RenderJob& job, std::size_t max_bytes) {
    if (job.aovs.empty()) return "";
    if (job.sampling.adaptive())
        return "--aov with adaptive anti-aliasing (--aa-threshold) is not supported yet: its pixels' centres are "
               "rendered apart from their samples";
    AovPlan plan;
    if (std::string problem = AovPlan::make(job.aovs, job.integrator.mode, scene.data.lights.size(), plan);
        !problem.empty())
        return problem;
    const PixelRegion r = job.render_region();
    const std::size_t bytes =
        3 * sizeof(float) * std::size_t(plan.channels()) * std::size_t(r.width()) * std::size_t(r.height());
    if (bytes > max_bytes)
        return "the " + std::to_string(plan.layers().size()) + " layers need about " + describe_bytes(bytes) +
               " of memory, more than the " + describe_bytes(max_bytes) + " left besides the image (--max-memory)";
    return aov_refusal(*make_integrator(scene, job.camera_for(scene), job.integrator));
}

Image enlarge_nearest(const Image& small, int width, int height) {
    Image big(width, height);
    if (small.width <= 0 || small.height <= 0) return big;
    for (int y = 0; y < height; ++y) {
        const int sy = int(std::int64_t(y) * small.height / height);
        for (int x = 0; x < width; ++x) {
            const int sx = int(std::int64_t(x) * small.width / width);
            std::memcpy(&big.rgb[(std::size_t(y) * width + x) * 3], &small.rgb[(std::size_t(sy) * small.width + sx) * 3], 3);
        }
    }
    return big;
}

}  // namespace whitted
