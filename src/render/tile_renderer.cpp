#include "render/tile_renderer.h"

#include <algorithm>
#include <cmath>

#include "accel/scene.h"

namespace whitted {
namespace {

glm::vec3 clamped(const glm::vec3& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }

}  // namespace

TileRenderer::TileRenderer(const Integrator& integrator, const RenderJob& job)
    : integrator_(integrator), job_(job), camera_(integrator.camera()),
      sampler_(job.sampling.aa, job.sampling.spp, job.sampling.seed), clamp_(integrator.clamps_samples()),
      timed_(!integrator.scene().motion.empty()) {
    const int n = sampler_.samples_per_pixel();
    s0_ = std::clamp(job.sampling.adaptive() ? 0 : job.sample_begin, 0, n);
    counts_.timing = job.time_rays;
    s1_ = job.sampling.adaptive() || job.sample_end < 0 ? n : std::clamp(job.sample_end, s0_, n);
    const int ts = std::max(1, job.tile_size);
    const int apron = std::min(ts + 2, job.width);  // adaptive: the tile and a pixel around it
    band_w_ = job.sampling.adaptive() ? apron : std::min(ts, job.width);
    band_.resize(std::size_t(band_w_) * kPacketHeight);
    if (job.sampling.adaptive()) centres_.resize(std::size_t(apron) * std::size_t(std::min(ts + 2, job.height)));
    xs_.resize(std::size_t(ts));
}

bool TileRenderer::stop_requested() const { return job_.cancel && job_.cancel->load(std::memory_order_relaxed); }

glm::vec3 TileRenderer::displayed(const glm::vec3& c) {
    if (clamp_) return clamped(c);  // §7's conversion per sample: NaN → 0, +inf → 1
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) {
        ++counts_.rejected;  // never a NaN or infinite pixel: the sample counts as black
        return glm::vec3(0.0f);
    }
    return c;
}

Ray camera_sample_ray(const Camera& camera, const Sampler& sampler, int width, int height, int x, int y,
                      std::uint32_t index, bool timed) {
    if (sampler.centred()) {  // the pixel's centre through the lens centre, mid-shutter: no sampler arithmetic
        Ray ray = camera.pinhole_ray(width, height, float(x) + 0.5f, float(y) + 0.5f);
        if (timed) ray.time = 0.5f;
        return ray;
    }
    const SampleKey key{std::uint32_t(x), std::uint32_t(y), index};
    const glm::vec2 at = sampler.pixel_offset(key);
    // A pinhole reads no lens dimension (its rays ignore it).
    const glm::vec2 lens = camera.is_pinhole() ? glm::vec2(0.5f) : sampler.get2d(key, dimension::kLens);
    Ray ray = camera.generate_ray(width, height, float(x) + at.x, float(y) + at.y, lens);
    if (timed) ray.time = sampler.get2d(key, dimension::kTime).x;
    return ray;
}

inline Ray TileRenderer::camera_ray(const Sampler& sampler, int x, int y, std::uint32_t index) const {
    if (sampler.centred() && !timed_)  // camera_sample_ray's first case, inline: the ray of every one-sample render
        return camera_.pinhole_ray(job_.width, job_.height, float(x) + 0.5f, float(y) + 0.5f);
    return camera_sample_ray(camera_, sampler, job_.width, job_.height, x, y, index, timed_);
}

bool TileRenderer::active(int x, int y) const {
    const PixelRegion r = job_.render_region();
    return (*job_.active)[std::size_t(y - r.y0) * std::size_t(r.width()) + std::size_t(x - r.x0)] != 0;
}

bool TileRenderer::render(const Tile& t, Film& film) {
    if (s0_ >= s1_) return !stop_requested();
    if (!job_.sampling.adaptive()) {
        if (s1_ - s0_ == 1 && !job_.active) {
            for (int y = t.y0; y < t.y1; ++y) {
                if (stop_requested()) return false;
                if ((y - t.y0) % kPacketHeight == 0 && !trace_band(sampler_, t, y, std::uint32_t(s0_))) return false;
                for (int x = t.x0; x < t.x1; ++x) film.add(x, y, displayed(band_at(t, x, y)));
            }
            return true;
        }
        for (int y = t.y0; y < t.y1; ++y) {
            if (stop_requested()) return false;
            int n = 0;
            for (int x = t.x0; x < t.x1; ++x)
                if (!job_.active || active(x, y)) xs_[std::size_t(n++)] = x;
            if (!add_samples(y, n, s0_, s1_, film)) return false;
        }
        return true;
    }
    // Adaptive: first the centre colours of the tile and of the pixels around it (so that the
    // pixels at a tile's edge compare with their neighbours in the next tile as anywhere else),
    // then every sample only where a centre differs from a neighbour.
    const Tile apron{std::max(0, t.x0 - 1), std::max(0, t.y0 - 1), std::min(job_.width, t.x1 + 1),
                     std::min(job_.height, t.y1 + 1)};
    for (int y = apron.y0; y < apron.y1; ++y) {
        if (stop_requested()) return false;
        if ((y - apron.y0) % kPacketHeight == 0 && !trace_band(centre_sampler_, apron, y, 0)) return false;
        for (int x = apron.x0; x < apron.x1; ++x) centre_at(apron, x, y) = clamped(band_at(apron, x, y));
    }
    for (int y = t.y0; y < t.y1; ++y) {
        if (stop_requested()) return false;
        int n = 0;
        for (int x = t.x0; x < t.x1; ++x) {
            if (differs(apron, x, y)) xs_[std::size_t(n++)] = x;
            else film.add(x, y, centre_at(apron, x, y));
        }
        if (!add_samples(y, n, s0_, s1_, film)) return false;
    }
    return true;
}

bool TileRenderer::trace_band(const Sampler& sampler, const Tile& region, int y0, std::uint32_t index) {
    band_y0_ = y0;
    for (int x0 = region.x0; x0 < region.x1; x0 += kPacketWidth) {
        // A packet can take long (a deep mirror-and-glass tree is up to kMaxSecondaryRays a sample).
        if (stop_requested()) return false;
        // Packets cut by the region's edges leave their outside lanes off.
        CameraBatch batch;
        for (int l = 0; l < kPacketSize; ++l) {
            const int x = x0 + l % kPacketWidth, y = y0 + l / kPacketWidth;
            if (x >= region.x1 || y >= region.y1) continue;
            batch.rays[l] = camera_ray(sampler, x, y, index);
            batch.keys[l] = {std::uint32_t(x), std::uint32_t(y), index};
            batch.active |= 1u << l;
        }
        glm::vec3 colors[kPacketSize];
        integrator_.radiance(batch, sampler, colors, counts_);
        for (int l = 0; l < kPacketSize; ++l)
            if ((batch.active >> l) & 1) band_at(region, x0 + l % kPacketWidth, y0 + l / kPacketWidth) = colors[l];
    }
    return true;
}

glm::vec3& TileRenderer::band_at(const Tile& region, int x, int y) {
    return band_[std::size_t(y - band_y0_) * std::size_t(band_w_) + std::size_t(x - region.x0)];
}

// The samples of the listed pixels, pixel after pixel and sample after sample within each, are
// cut into packets in that order, so a packet covers neighbouring samples whatever their count.
bool TileRenderer::add_samples(int y, int n, int s0, int s1, Film& film) {
    // (64 bits: a row of 1024 pixels of 16.7 million samples each has more samples than an int holds.)
    const std::int64_t per_pixel = s1 - s0, total = n * per_pixel;
    for (std::int64_t k0 = 0; k0 < total; k0 += kPacketSize) {
        // One pixel may have a million samples (--spp 65536 --aa 16): looked at every packet.
        if (stop_requested()) return false;
        const int lanes = int(std::min<std::int64_t>(kPacketSize, total - k0));
        CameraBatch batch;
        for (int l = 0; l < lanes; ++l) {
            const std::int64_t k = k0 + l;
            const int x = xs_[std::size_t(k / per_pixel)];
            const std::uint32_t index = std::uint32_t(s0 + k % per_pixel);
            batch.rays[l] = camera_ray(sampler_, x, y, index);
            batch.keys[l] = {std::uint32_t(x), std::uint32_t(y), index};
        }
        batch.active = (1u << lanes) - 1;
        glm::vec3 colors[kPacketSize];
        integrator_.radiance(batch, sampler_, colors, counts_);
        for (int l = 0; l < lanes; ++l) film.add(xs_[std::size_t((k0 + l) / per_pixel)], y, displayed(colors[l]));
    }
    return true;
}

glm::vec3& TileRenderer::centre_at(const Tile& apron, int x, int y) {
    return centres_[std::size_t(y - apron.y0) * std::size_t(apron.x1 - apron.x0) + std::size_t(x - apron.x0)];
}

const glm::vec3& TileRenderer::centre_at(const Tile& apron, int x, int y) const {
    return centres_[std::size_t(y - apron.y0) * std::size_t(apron.x1 - apron.x0) + std::size_t(x - apron.x0)];
}

bool TileRenderer::differs(const Tile& apron, int x, int y) const {
    const glm::vec3& c = centre_at(apron, x, y);
    auto far = [&](int nx, int ny) {
        if (nx < apron.x0 || nx >= apron.x1 || ny < apron.y0 || ny >= apron.y1) return false;  // beyond the image
        const glm::vec3 d = glm::abs(centre_at(apron, nx, ny) - c);
        return std::max(d.x, std::max(d.y, d.z)) > job_.sampling.aa_threshold;
    };
    return far(x - 1, y) || far(x + 1, y) || far(x, y - 1) || far(x, y + 1);
}

}  // namespace whitted
