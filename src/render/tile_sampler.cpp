#include "render/tile_sampler.h"

#include <algorithm>
#include <cmath>

namespace whitted {
namespace {

glm::vec3 clamped(const glm::vec3& c) { return {clamp01(c.x), clamp01(c.y), clamp01(c.z)}; }

void store(Image& image, int x, int y, const glm::vec3& c) {
    std::uint8_t* p = &image.rgb[(std::size_t(y) * image.width + x) * 3];
    p[0] = to_byte(c.x);
    p[1] = to_byte(c.y);
    p[2] = to_byte(c.z);
}

bool stop_requested(const std::atomic<bool>* cancel) { return cancel && cancel->load(std::memory_order_relaxed); }

}  // namespace

Ray camera_ray(const Camera& cam, int width, int height, float x, float y) {
    const float aspect = float(width) / float(height);
    const float sx = (2.0f * x / float(width) - 1.0f) * cam.tan_half_fov * aspect;
    const float sy = (1.0f - 2.0f * y / float(height)) * cam.tan_half_fov;
    return Ray{cam.eye, glm::normalize(cam.forward + sx * cam.right + sy * cam.up)};
}

TileSampler::TileSampler(const WhittedIntegrator& integrator, const Camera& camera, int image_w, int image_h,
                         int tile_size, const Sampling& sampling)
    : integrator_(integrator), camera_(camera), image_w_(image_w), image_h_(image_h), sampling_(sampling) {
    sampling_.aa = std::clamp(sampling_.aa, 1, kMaxAa);
    // Decided once: a threshold that is not a positive number (0, negative, NaN) means every pixel.
    if (!(sampling_.threshold > 0.0f)) sampling_.threshold = 0.0f;
    const bool adaptive = sampling_.aa > 1 && sampling_.threshold > 0.0f;
    const int apron = std::min(tile_size + 2, image_w);  // adaptive: the tile and a pixel around it
    band_w_ = adaptive ? apron : std::min(tile_size, image_w);
    if (sampling_.aa == 1 || adaptive) band_.resize(std::size_t(band_w_) * kPacketHeight);
    if (adaptive) centres_.resize(std::size_t(apron) * std::min(tile_size + 2, image_h));
    if (sampling_.aa > 1) {
        xs_.resize(std::size_t(tile_size));
        means_.resize(std::size_t(tile_size));
    }
}

bool TileSampler::render(const Tile& t, Image& image, RayCounts& counts, const std::atomic<bool>* cancel) {
    if (sampling_.aa == 1) {
        for (int y = t.y0; y < t.y1; ++y) {
            if (stop_requested(cancel)) return false;
            if ((y - t.y0) % kPacketHeight == 0) trace_band(t, y, counts);
            for (int x = t.x0; x < t.x1; ++x) store(image, x, y, band_at(t, x, y));
        }
        return true;
    }
    if (sampling_.threshold <= 0.0f) {
        for (int y = t.y0; y < t.y1; ++y) {
            if (stop_requested(cancel)) return false;
            const int n = t.x1 - t.x0;
            for (int k = 0; k < n; ++k) xs_[std::size_t(k)] = t.x0 + k;
            supersample(y, n, counts);
            for (int k = 0; k < n; ++k) store(image, t.x0 + k, y, means_[std::size_t(k)]);
        }
        return true;
    }
    // Adaptive: first the centre colours of the tile and of the pixels around it (so that the
    // pixels at a tile's edge compare with their neighbours in the next tile as anywhere else),
    // then aa × aa rays only where a centre differs from a neighbour.
    const Tile apron{std::max(0, t.x0 - 1), std::max(0, t.y0 - 1), std::min(image_w_, t.x1 + 1),
                     std::min(image_h_, t.y1 + 1)};
    for (int y = apron.y0; y < apron.y1; ++y) {
        if (stop_requested(cancel)) return false;
        if ((y - apron.y0) % kPacketHeight == 0) trace_band(apron, y, counts);
        for (int x = apron.x0; x < apron.x1; ++x) centre_at(apron, x, y) = clamped(band_at(apron, x, y));
    }
    for (int y = t.y0; y < t.y1; ++y) {
        if (stop_requested(cancel)) return false;
        int n = 0;
        for (int x = t.x0; x < t.x1; ++x) {
            if (differs(apron, x, y)) xs_[std::size_t(n++)] = x;
            else store(image, x, y, centre_at(apron, x, y));
        }
        supersample(y, n, counts);
        for (int k = 0; k < n; ++k) store(image, xs_[std::size_t(k)], y, means_[std::size_t(k)]);
    }
    return true;
}

void TileSampler::trace_band(const Tile& region, int y0, RayCounts& counts) {
    band_y0_ = y0;
    for (int x0 = region.x0; x0 < region.x1; x0 += kPacketWidth) {
        // Packets cut by the region's edges leave their outside lanes off.
        Ray rays[kPacketSize];
        unsigned active = 0;
        for (int l = 0; l < kPacketSize; ++l) {
            const int x = x0 + l % kPacketWidth, y = y0 + l / kPacketWidth;
            if (x >= region.x1 || y >= region.y1) continue;
            rays[l] = camera_ray(camera_, image_w_, image_h_, float(x) + 0.5f, float(y) + 0.5f);
            active |= 1u << l;
        }
        Hit hits[kPacketSize];
        const unsigned found = integrator_.camera_hits(rays, active, hits);
        glm::vec3 colors[kPacketSize];
        integrator_.camera_packet(rays, active, hits, found, colors, counts);
        for (int l = 0; l < kPacketSize; ++l)
            if ((active >> l) & 1) band_at(region, x0 + l % kPacketWidth, y0 + l / kPacketWidth) = colors[l];
    }
}

glm::vec3& TileSampler::band_at(const Tile& region, int x, int y) {
    return band_[std::size_t(y - band_y0_) * std::size_t(band_w_) + std::size_t(x - region.x0)];
}

// The rays of the listed pixels, pixel after pixel and sub-pixel row by row within each, are cut
// into packets in that order, so a packet covers neighbouring sub-pixels whatever aa is.
void TileSampler::supersample(int y, int n, RayCounts& counts) {
    const int aa = sampling_.aa, per_pixel = aa * aa, total = n * per_pixel;
    const float step = 1.0f / float(aa);
    std::fill(means_.begin(), means_.begin() + n, glm::vec3(0.0f));
    for (int k0 = 0; k0 < total; k0 += kPacketSize) {
        const int lanes = std::min(kPacketSize, total - k0);
        Ray rays[kPacketSize];
        for (int l = 0; l < lanes; ++l) {
            const int k = k0 + l, x = xs_[std::size_t(k / per_pixel)], sub = k % per_pixel;
            rays[l] = camera_ray(camera_, image_w_, image_h_, float(x) + (float(sub % aa) + 0.5f) * step,
                                 float(y) + (float(sub / aa) + 0.5f) * step);
        }
        const unsigned active = (1u << lanes) - 1;
        Hit hits[kPacketSize];
        const unsigned found = integrator_.camera_hits(rays, active, hits);
        glm::vec3 colors[kPacketSize];
        integrator_.camera_packet(rays, active, hits, found, colors, counts);
        for (int l = 0; l < lanes; ++l) means_[std::size_t((k0 + l) / per_pixel)] += clamped(colors[l]);
    }
    for (int k = 0; k < n; ++k) means_[std::size_t(k)] /= float(per_pixel);
}

glm::vec3& TileSampler::centre_at(const Tile& apron, int x, int y) {
    return centres_[std::size_t(y - apron.y0) * std::size_t(apron.x1 - apron.x0) + std::size_t(x - apron.x0)];
}

const glm::vec3& TileSampler::centre_at(const Tile& apron, int x, int y) const {
    return centres_[std::size_t(y - apron.y0) * std::size_t(apron.x1 - apron.x0) + std::size_t(x - apron.x0)];
}

bool TileSampler::differs(const Tile& apron, int x, int y) const {
    const glm::vec3& c = centre_at(apron, x, y);
    auto far = [&](int nx, int ny) {
        if (nx < apron.x0 || nx >= apron.x1 || ny < apron.y0 || ny >= apron.y1) return false;  // beyond the image
        const glm::vec3 d = glm::abs(centre_at(apron, nx, ny) - c);
        return std::max(d.x, std::max(d.y, d.z)) > sampling_.threshold;
    };
    return far(x - 1, y) || far(x + 1, y) || far(x, y - 1) || far(x, y + 1);
}

}  // namespace whitted
